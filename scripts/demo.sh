#!/usr/bin/env bash
# The main job: set up MeshLab and the plugin, then simplify a shipped sample mesh inside
# meshlabserver with our filter beside MeshLab's Quadric Edge Collapse Decimation at the same
# target, and print faces, time and MeshLab's own Hausdorff distance for both.
#   scripts/demo.sh [MESH] [RATIO]      (default meshes/fandisk.off, 0.1: keep 10 % of the faces)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
mesh=${1:-$top/meshes/fandisk.off}
ratio=${2:-0.1}
"$top/scripts/setup.sh"
"$top/scripts/build.sh" -DVRS_BUILD_TESTS=OFF
"$top/scripts/compare_in_meshlab.sh" "$mesh" "$ratio" "$top/out"
echo
echo "Open them side by side: meshlab $top/out/$(basename "${mesh%.*}")-ours.ply $top/out/$(basename "${mesh%.*}")-qecd.ply"
echo "The same simplification from the command line: build/bin/vrsimplify $mesh out.ply --ratio $ratio"
