#!/usr/bin/env bash
# The benchmark: vrsimplify beside MeshLab's quadric decimation, meshoptimizer and vtkDecimatePro
# on CGAL's real meshes at 50 %, 10 % and 1 % (time, peak memory, symmetric Hausdorff), plus the
# hash-table ablation; writes bench/results.csv and bench/REPORT.md with plots in bench/plots/.
#   scripts/bench.sh [--large] [MESH_NAME...]   (default: the six meshes of the report)
# --large adds the scaling runs at 10 %: bunny00 Loop-subdivided to 1.2 M, 4.8 M and 19 M faces
# and fractal terrains of 2049^2 and 4097^2 vertices (made in third_party/bench-inputs/).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/scripts/setup.sh"
"$top/scripts/build.sh"
data=$top/third_party/cgal-data/data/meshes
large=0
if [ "${1:-}" = --large ]; then large=1; shift; fi
meshes=("$@")
[ ${#meshes[@]} -gt 0 ] || meshes=(bunny00 armadillo fandisk mushroom three_peaks elephant)
methods=ours,ours-factor,qecd,meshopt,vtk,ours-log,ours-heap,ours-int100,ours-int10000
csv=$top/bench/results.csv
first=--header
: >"$csv"
for m in "${meshes[@]}"; do
  echo "== $m" >&2
  "$top/build/bin/vrs_bench" "$data/$m.off" --name "$m" --methods "$methods" $first >>"$csv" ||
    echo "some runs on $m failed: see their rows" >&2
  first=
done
if [ $large -eq 1 ]; then
  inputs=$top/third_party/bench-inputs
  mkdir -p "$inputs"
  for l in 2 3 4; do
    [ -s "$inputs/bunny_loop$l.ply" ] || "$top/build/bin/vrs_bench" --loop "$data/bunny00.off" $l "$inputs/bunny_loop$l.ply" >&2
  done
  for k in 11 12; do
    [ -s "$inputs/terrain_k$k.ply" ] || "$top/build/bin/vrs_bench" --terrain $k "$inputs/terrain_k$k.ply" >&2
  done
  for m in bunny_loop2 bunny_loop3 bunny_loop4 terrain_k11 terrain_k12; do
    echo "== $m" >&2
    # vtkDecimatePro needs minutes past a million faces: it runs on the smallest only.
    methods=ours,ours-factor,meshopt,qecd
    [ $m = bunny_loop2 ] && methods=ours,ours-factor,meshopt,qecd,vtk
    "$top/build/bin/vrs_bench" "$inputs/$m.ply" --name "$m" --ratios 0.1 --methods $methods \
      --samples 200000 >>"$csv" || echo "some runs on $m failed: see their rows" >&2
  done
fi
# Renders at 1 %: the original and each method's result, flat shading with edges (VTK, offscreen).
renders=$top/bench/renders
work=$(mktemp -d)
mkdir -p "$renders"
for m in fandisk bunny00; do
  "$top/build/bin/vrs_bench" "$data/$m.off" --name "$m" --ratios 0.01 --methods ours,qecd,meshopt \
    --samples 1000 --save "$work" >/dev/null
  view="--azimuth 30 --elevation 20"
  [ $m = bunny00 ] && view="--azimuth 0 --elevation 0"
  # shellcheck disable=SC2086
  "$top/scripts/lib/on_display.sh" "$top/build/bin/vrs_render" "$data/$m.off" "$renders/${m}_original.png" $view
  for method in ours qecd meshopt; do
    # shellcheck disable=SC2086
    "$top/scripts/lib/on_display.sh" "$top/build/bin/vrs_render" "$work/${m}_0.01_$method.ply" \
      "$renders/${m}_$method.png" $view
  done
done
rm -rf "$work"
"$top/bench/make_report.sh" "$csv" "$top/bench"
echo "wrote $csv and $top/bench/REPORT.md" >&2
