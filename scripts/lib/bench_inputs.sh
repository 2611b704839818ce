#!/usr/bin/env bash
# The large benchmark inputs, made once into third_party/bench-inputs: bunny00 Loop-subdivided
# to 1.2 M faces, the refined elephant Loop-subdivided to 5.7 M faces, and that elephant with 7
# UV charts (bench/attributed_mesh.py). Prints the folder.
#   scripts/lib/bench_inputs.sh VRS_BENCH PYTHON
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
bench=$1 python=$2
inputs=$top/third_party/bench-inputs data=$top/third_party/cgal-data/data/meshes
mkdir -p "$inputs"
[ -s "$inputs/bunny_loop2.ply" ] || "$bench" --loop "$data/bunny00.off" 2 "$inputs/bunny_loop2.ply" >&2
[ -s "$inputs/elephant_loop3.ply" ] || "$bench" --loop "$data/refined_elephant.off" 3 "$inputs/elephant_loop3.ply" >&2
[ -s "$inputs/elephant_textured.ply" ] ||
  "$python" "$top/bench/attributed_mesh.py" textured "$inputs/elephant_loop3.ply" "$inputs/elephant_textured.ply" >&2
echo "$inputs"
