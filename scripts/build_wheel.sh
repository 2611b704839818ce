#!/usr/bin/env bash
# Builds the wheel users install, into dist/: the numpy API (vrsimplify._core), the `vrsimplify`
# command, and the MeshLab filter built for pymeshlab 2025.7 (`import vrsimplify.pymeshlab`).
# auditwheel tags it manylinux and checks it needs nothing a manylinux system lacks; the plugin's
# MeshLab and Qt libraries are pymeshlab's own, loaded by pymeshlab before the plugin, so they
# are excluded rather than copied in. Build tools (scikit-build-core, nanobind) are pinned in
# pyproject.toml, auditwheel in requirements.txt.
#   scripts/build_wheel.sh            -> dist/vrsimplify-VERSION-cp3XX-...-manylinux_*.whl
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cache=${VRS_CACHE:-/var/cache/vrsimplify}
"$top/scripts/setup.sh" >/dev/null
python=$cache/venv/bin/python
pymeshlab=$("$python" -c 'import os, pymeshlab; print(os.path.dirname(pymeshlab.__file__))')
raw=$(mktemp -d)
trap 'rm -rf "$raw"' EXIT
log=$top/build/wheel.log
mkdir -p "$top/build" "$top/dist"
echo "build_wheel: building (log: $log)"
if ! "$python" -m pip wheel --no-deps --disable-pip-version-check -w "$raw" "$top" \
    --config-settings=cmake.define.VRS_BUILD_PLUGIN=ON \
    --config-settings=cmake.define.VRS_PYMESHLAB_DIR="$pymeshlab" \
    --config-settings=cmake.define.VRS_MESHLAB2025_SOURCE="$top/third_party/meshlab-2025.07" >"$log" 2>&1; then
  tail -n 40 "$log" >&2
  exit 1
fi
wheel=$(ls "$raw"/vrsimplify-*.whl)
for member in vrsimplify/bin/vrsimplify vrsimplify/plugins/libfilter_vertex_removal.so; do
  "$python" -c 'import sys, zipfile; sys.exit(sys.argv[2] not in zipfile.ZipFile(sys.argv[1]).namelist())' \
    "$wheel" "$member" || { echo "build_wheel: $member missing from the wheel" >&2; exit 1; }
done
rm -f "$top"/dist/vrsimplify-*.whl
PATH="$cache/venv/bin:$PATH" "$python" -m auditwheel repair --exclude libmeshlab-common.so --exclude 'libQt5*.so.5' \
  -w "$top/dist" "$wheel" >>"$log" 2>&1 || { tail -n 20 "$log" >&2; exit 1; }
out=$(ls "$top"/dist/vrsimplify-*.whl)
echo "build_wheel: $out ($(du -k "$out" | cut -f1) KiB)"
