#!/usr/bin/env bash
# The whole data set the quality benchmarks run on, one file per line: every mesh of CGAL's
# data set (Debian's libcgal-demo, unpacked by scripts/setup.sh) and every OBJ/PLY/STL/OFF model
# of assimp's test models (Debian's assimp-testmodels) but its deliberately invalid ones, and
# with --cad the CAD data set (scripts/lib/cad_parts.sh: parts modelled in build123d).
#   scripts/lib/bench_meshes.sh [--cad]
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
find "$top/third_party/cgal-data/data/meshes" -maxdepth 1 -type f | sort
find /usr/share/assimp/models -type f \( -iname '*.obj' -o -iname '*.ply' -o -iname '*.stl' \
  -o -iname '*.off' \) -not -path '*/invalid/*' | sort
if [ "${1:-}" = --cad ]; then
  find "$("$top/scripts/lib/cad_parts.sh")" -maxdepth 1 -name '*.stl' | sort
fi
