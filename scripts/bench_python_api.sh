#!/usr/bin/env bash
# The numpy API's cost over the core at 1.2 M faces (bunny00 Loop-subdivided twice, as
# scripts/bench_speed.sh makes it), and two Python threads at once: bench/python_api.py with
# the wheel of scripts/build_wheel.sh in the benchmark's virtual environment
# (scripts/bench_python_peers.sh makes it). Writes bench/PYTHON_API.md.
#   scripts/bench_python_api.sh [REPEATS]     (default 3, alternated, medians)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cache=${VRS_CACHE:-/var/cache/vrsimplify}
"$top/scripts/build.sh" >/dev/null
"$top/scripts/build_wheel.sh" >/dev/null
venv=$cache/peers-venv
[ -x "$venv/bin/python" ] || { echo "bench_python_api: run scripts/bench_python_peers.sh first (it makes $venv)" >&2; exit 1; }
"$venv/bin/pip" install -q --disable-pip-version-check --no-deps --force-reinstall "$top"/dist/vrsimplify-*.whl
mesh=$top/third_party/bench-inputs/bunny_loop2.ply
[ -s "$mesh" ] || { mkdir -p "$(dirname "$mesh")"
  "$top/build/bin/vrs_bench" --loop "$top/third_party/cgal-data/data/meshes/bunny00.off" 2 "$mesh" >&2; }
{
  echo "# The numpy API's cost"
  echo
  echo "\`scripts/bench_python_api.sh\`, $(date -u +%F), $(nproc) cores ($(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -n 1)), CPython $("$venv/bin/python" -c 'import platform; print(platform.python_version())')."
  echo
  (cd "$top/bench" && "$venv/bin/python" python_api.py "$top/build/bin/vrsimplify" "$mesh" "${1:-3}")
} | tee "$top/bench/PYTHON_API.md"
