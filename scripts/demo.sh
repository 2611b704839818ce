#!/usr/bin/env bash
# The main job: set up (Debian packages, MeshLab's sources, pymeshlab in a virtual environment),
# build the plugin, then simplify a shipped sample mesh in pymeshlab with our filter beside
# MeshLab's Quadric Edge Collapse Decimation at the same target, and print faces, time and
# MeshLab's own Hausdorff distance for both. The same comparison inside MeshLab 2020.09's
# meshlabserver: scripts/compare_in_meshlab.sh MESH RATIO.
#   scripts/demo.sh [MESH] [RATIO]      (default meshes/fandisk.off, 0.1: keep 10 % of the faces)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
mesh=${1:-$top/meshes/fandisk.off}
ratio=${2:-0.1}
"$top/scripts/setup.sh"
# The build's output goes to a log: a first run reads as the comparison, not pages of make.
mkdir -p "$top/build"
log=$top/build/demo-build.log
echo "demo: building (log: $log)"
"$top/scripts/build.sh" -DVRS_BUILD_TESTS=OFF >"$log" 2>&1 || { tail -n 40 "$log" >&2; exit 1; }
python=$(ls "${VRS_CACHE:-/var/cache/vrsimplify}"/venv/bin/python)
"$python" "$top/scripts/compare_in_pymeshlab.py" "$top/build/pymeshlab/plugins/libfilter_vertex_removal.so" \
  "$mesh" "$ratio" "$top/out"
echo
echo "Open them side by side: meshlab $top/out/$(basename "${mesh%.*}")-ours.ply $top/out/$(basename "${mesh%.*}")-qecd.ply"
echo "In your own pymeshlab scripts: plugin/examples/pymeshlab_example.py"
echo "From the command line: build/bin/vrsimplify $mesh out.ply --ratio $ratio"
