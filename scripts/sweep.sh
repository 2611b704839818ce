#!/usr/bin/env bash
# The full robustness sweep: every mesh of CGAL's data set and of assimp's test models at 50 %,
# 10 % and 1 % with every invariant (tests/sweep/), then the same through the real
# meshlabserver on the representative subset. --large adds the 19 M-triangle run: the Loop-
# subdivided bunny to 1 % (peak memory measured by /usr/bin/time), with the progress callback
# shown, the invariants checked, and a run stopped by the callback at 50 % checked too.
#   scripts/sweep.sh [--large]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/scripts/setup.sh"
"$top/scripts/build.sh" -DVRS_BUILD_TESTS=ON
b=$top/build
data=$top/third_party/cgal-data/data/meshes
bash "$top/tests/sweep/run_sweep.sh" "$b/bin/vrs_sweep" "$data" "$b/sweep-full"
bash "$top/tests/plugin/test_meshlabserver_sweep.sh" "$top" "$data" "$b/meshlabserver-sweep"
if [ "${1:-}" = --large ]; then
  big=$top/third_party/bench-inputs/bunny_loop4.ply
  mkdir -p "$(dirname "$big")"
  [ -s "$big" ] || "$b/bin/vrs_bench" --loop "$data/bunny00.off" 4 "$big"
  echo "== 19 M triangles to 1 % with the CLI (peak memory: Maximum resident set size)"
  /usr/bin/time -v "$b/bin/vrsimplify" "$big" "$b/bunny_loop4_1pct.ply" --ratio 0.01 --json \
    2> >(grep -E "Maximum resident|Elapsed" >&2)
  echo "== the same run in-process: progress, every invariant, determinism"
  "$b/bin/vrs_sweep" --ratios 0.01 --progress "$big"
  echo "== stopped by the progress callback at 50 %: the mesh left must keep every invariant"
  "$b/bin/vrs_sweep" --ratios 0.01 --cancel-at 0.5 "$big"
fi
