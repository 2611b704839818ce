#!/usr/bin/env bash
# Builds the wheels users install, into dist/: the numpy API (vrsimplify._core), the `vrsimplify`
# command, and the MeshLab filter built for pymeshlab 2025.7 (`import vrsimplify.pymeshlab`).
# Two wheels: cp311 (Debian's python3) and cp312-abi3 (the stable ABI: CPython 3.12, 3.13,
# 3.14 and later), built with a CPython 3.13 of this machine (scripts/lib/cpython.sh), so both
# need only the glibc of Debian 12 / Ubuntu 22.04. auditwheel tags them manylinux and checks
# they need nothing a manylinux system lacks; the plugin's MeshLab and Qt libraries are
# pymeshlab's own, loaded by pymeshlab before the plugin, so they are excluded rather than
# copied in. Also the sdist (`pip install vrsimplify-*.tar.gz` builds the numpy API and the
# command where a compiler is). Build tools (scikit-build-core, nanobind) are pinned in
# pyproject.toml, auditwheel in requirements.txt.
#   scripts/build_wheel.sh   -> dist/vrsimplify-VERSION-cp311-cp311-manylinux_*.whl,
#                               dist/vrsimplify-VERSION-cp312-abi3-manylinux_*.whl,
#                               dist/vrsimplify-VERSION.tar.gz
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cache=${VRS_CACHE:-/var/cache/vrsimplify}
"$top/scripts/setup.sh" >/dev/null
python=$cache/venv/bin/python
python313=$("$top/scripts/lib/cpython.sh")
# The interpreter that builds the abi3 wheel needs only pip (the build tools come pinned
# through pyproject.toml's build isolation).
[ -x "$cache/venv-build313/bin/pip" ] || { rm -rf "$cache/venv-build313"; "$python313" -m venv "$cache/venv-build313"; }
pymeshlab=$("$python" -c 'import os, pymeshlab; print(os.path.dirname(pymeshlab.__file__))')
raw=$(mktemp -d)
trap 'rm -rf "$raw"' EXIT
log=$top/build/wheel.log
mkdir -p "$top/build" "$top/dist"
: >"$log"
rm -f "$top"/dist/vrsimplify-*.whl "$top"/dist/vrsimplify-*.tar.gz
for builder in "$python" "$cache/venv-build313/bin/python"; do
  echo "build_wheel: building with $("$builder" -c 'import sys; print("CPython %d.%d" % sys.version_info[:2])') (log: $log)"
  if ! "$builder" -m pip wheel --no-deps --disable-pip-version-check -w "$raw/$(basename "$(dirname "$(dirname "$builder")")")" "$top" \
      --config-settings=cmake.define.VRS_BUILD_PLUGIN=ON \
      --config-settings=cmake.define.VRS_PYMESHLAB_DIR="$pymeshlab" \
      --config-settings=cmake.define.VRS_MESHLAB2025_SOURCE="$top/third_party/meshlab-2025.07" >>"$log" 2>&1; then
    tail -n 40 "$log" >&2
    exit 1
  fi
done
for wheel in "$raw"/*/vrsimplify-*.whl; do
  for member in vrsimplify/bin/vrsimplify vrsimplify/plugins/libfilter_vertex_removal.so; do
    "$python" -c 'import sys, zipfile; sys.exit(sys.argv[2] not in zipfile.ZipFile(sys.argv[1]).namelist())' \
      "$wheel" "$member" || { echo "build_wheel: $member missing from $(basename "$wheel")" >&2; exit 1; }
  done
  PATH="$cache/venv/bin:$PATH" "$python" -m auditwheel repair --exclude libmeshlab-common.so --exclude 'libQt5*.so.5' \
    -w "$top/dist" "$wheel" >>"$log" 2>&1 || { tail -n 20 "$log" >&2; exit 1; }
done
abi3=$(ls "$top"/dist/vrsimplify-*-cp312-abi3-*.whl 2>/dev/null) ||
  { echo "build_wheel: no cp312-abi3 wheel was made" >&2; exit 1; }
# The tag alone proves nothing: the module in it must be the stable-ABI build.
"$python" -c 'import sys, zipfile; sys.exit(not any(n.endswith("_core.abi3.so") for n in zipfile.ZipFile(sys.argv[1]).namelist()))' "$abi3" ||
  { echo "build_wheel: $(basename "$abi3") holds no _core.abi3.so" >&2; exit 1; }
# The sdist: what `pip install` builds from on a machine with a compiler.
"$python" -m build --sdist --outdir "$top/dist" "$top" >>"$log" 2>&1 || { tail -n 20 "$log" >&2; exit 1; }
for out in "$top"/dist/vrsimplify-*.whl "$top"/dist/vrsimplify-*.tar.gz; do
  echo "build_wheel: $out ($(du -k "$out" | cut -f1) KiB)"
done
