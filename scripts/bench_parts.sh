#!/usr/bin/env bash
# What simplification by parts does to the error: large meshes (data-set meshes Loop-subdivided
# past the size that is cut, 65 536 vertices) at 50/10/1 %, our default run beside one queue
# from the start (ours-whole, Options::part_vertices = 0), one thread, side by side in one run;
# then the quality benchmark's tuning meshes cut into parts of 256 and 1024 vertices (every
# kind of mesh: CAD parts, open borders) against the default's rows. Writes bench/parts.csv
# and bench/PARTS.md.
#   scripts/bench_parts.sh [--samples S] [--no-small]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
samples=30000 small=1
while [ $# -gt 0 ]; do
  case $1 in
  --samples) samples=$2; shift 2 ;;
  --no-small) small=0; shift ;;
  *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
. "$top/scripts/lib/bench_setup.sh"
csv=$top/bench/parts.csv
first=--header
: >"$csv"
# mesh level: armadillo, man, diplodocus and bear are held out of the quality tuning.
for m in bunny00:2 armadillo:2 man:2 diplodocus:2 bear:2 fandisk_large:2 refined_elephant:1; do
  name=${m%%:*} level=${m##*:}
  file=$inputs/${name}_loop$level.ply
  [ -s "$file" ] || "$bench" --loop "$data/$name.off" "$level" "$file" >&2
  echo "== ${name}_loop$level" >&2
  "$bench" "$file" --name "${name}_loop$level" --ratios 0.5,0.1,0.01 \
    --methods ours,ours-whole --samples "$samples" $first >>"$csv"
  first=
done
small_csv=
if [ $small -eq 1 ]; then
  small_csv=$top/bench/parts_small.csv
  "$top/scripts/bench_quality.sh" --tuning --baseline none --samples "$samples" \
    --methods ours,ours-part256,ours-part1024 --csv "$small_csv"
fi
python3 "$top/bench/parts_report.py" "$csv" "$top/bench/PARTS.md" $small_csv
echo "wrote $csv and bench/PARTS.md" >&2
