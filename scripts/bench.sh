#!/usr/bin/env bash
# The benchmark: vrsimplify beside MeshLab's quadric decimation, meshoptimizer and vtkDecimatePro
# on CGAL's real meshes at 50 %, 10 % and 1 % (time, peak memory, symmetric Hausdorff), plus the
# hash-table ablation; writes bench/results.csv and bench/REPORT.md with plots in bench/plots/.
#   scripts/bench.sh [MESH_NAME...]     (default: the six meshes of the report)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/scripts/setup.sh"
"$top/scripts/build.sh" -DVRS_BUILD_TESTS=OFF
data=$top/third_party/cgal-data/data/meshes
meshes=("$@")
[ ${#meshes[@]} -gt 0 ] || meshes=(bunny00 armadillo fandisk mushroom three_peaks elephant)
methods=ours,qecd,meshopt,vtk,ours-log,ours-heap,ours-int100,ours-int10000
csv=$top/bench/results.csv
first=--header
: >"$csv"
for m in "${meshes[@]}"; do
  echo "== $m" >&2
  "$top/build/bin/vrs_bench" "$data/$m.off" --name "$m" --methods "$methods" $first >>"$csv"
  first=
done
"$top/bench/make_report.sh" "$csv" "$top/bench"
echo "wrote $csv and $top/bench/REPORT.md" >&2
