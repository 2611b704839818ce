#!/usr/bin/env bash
# vrsimplify's numpy API beside what Python users pip-install (fast-simplification, pyfqmr,
# meshoptimizer's wrapper, open3d; pinned in bench/requirements-peers.txt, in a virtual
# environment of their own under $VRS_CACHE with the wheel of scripts/build_wheel.sh), on the
# whole data set at the targets of bench/quality.csv: bench/python_peers.csv and
# bench/PYTHON_PEERS.md (bench/python_peers_report.py).
#   scripts/bench_python_peers.sh [--samples S] [MESH_FILE...]   (default: the whole set)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cache=${VRS_CACHE:-/var/cache/vrsimplify}
samples=30000
if [ "${1:-}" = --samples ]; then samples=$2; shift 2; fi
"$top/scripts/setup.sh" libusb-1.0-0 >/dev/null # open3d's wheel needs libusb
"$top/scripts/build.sh" >/dev/null
"$top/scripts/build_wheel.sh"
venv=$cache/peers-venv
"$top/scripts/lib/pinned_venv.sh" "$venv" "$top/bench/requirements-peers.txt"
"$venv/bin/pip" install -q --disable-pip-version-check --no-deps --force-reinstall "$top"/dist/vrsimplify-*.whl
files=("$@")
[ ${#files[@]} -gt 0 ] || mapfile -t files < <("$top/scripts/lib/bench_meshes.sh")
csv=$top/bench/python_peers.csv
"$venv/bin/python" "$top/bench/python_peers.py" "$top/build/bin/vrs_bench" "$top/bench/quality.csv" \
  "$csv" --samples "$samples" "${files[@]}"
python3 "$top/bench/python_peers_report.py" "$csv" "$top/bench/PYTHON_PEERS.md"
echo "bench_python_peers: $csv, $top/bench/PYTHON_PEERS.md"
