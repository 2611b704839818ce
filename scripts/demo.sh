#!/usr/bin/env bash
# The main job: set up, build, and simplify the shipped sample meshes, printing the reports.
#   scripts/demo.sh [RATIO]   (default 0.1: keep 10 % of the faces)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
ratio=${1:-0.1}
"$top/scripts/setup.sh"
"$top/scripts/build.sh" -DVRS_BUILD_TESTS=OFF
mkdir -p "$top/out"
run() { # name, mesh, extra options
  local name=$1 mesh=$2; shift 2
  echo
  echo "== $name: $mesh -> out/${name}.ply (ratio $ratio $*)"
  "$top/build/bin/vrsimplify" "$top/meshes/$mesh" "$top/out/${name}.ply" --ratio "$ratio" "$@"
}
run fandisk fandisk.off
run elephant elephant.off
run three_peaks three_peaks.off
echo
echo "Outputs are in $top/out/ (binary PLY; open them in MeshLab)."
