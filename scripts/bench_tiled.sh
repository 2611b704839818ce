#!/usr/bin/env bash
# Tiled, out-of-core runs against in-core ones (bench/TILED.md):
# - quality: bunny00 Loop-subdivided to 1.2 M and 4.8 M faces, terrains of 2 M, an elephant of
#   1.4 M (the last two held out of tuning), at 10 % and 1 %, in core and in
#   tiles (a budget of an eighth of what the in-core CLI needs, so dozens of tiles): faces,
#   mean and max surface error (vrs_bench --compare, 200 000 samples a side);
# - memory and time: the same bunny at 77 M faces (five subdivisions, made once into
#   third_party/bench-inputs/, 1.5 GB) at 1 % in core and with --memory 2G on 2 and 1 worker
#   processes: peak resident memory summed over every process of the run
#   (bench/tree_memory.py), wall time;
# - beyond memory: a 302 M-face terrain (5.7 GB, streamed out) at 1 % within 4 GB, with the
#   work directory's largest size (~30 GB of disk in all).
#   scripts/bench_tiled.sh [--no-large]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/scripts/setup.sh" >/dev/null
"$top/scripts/build.sh" >/dev/null
bin=$top/build/bin/vrsimplify bench=$top/build/bin/vrs_bench
inputs=$top/third_party/bench-inputs data=$top/third_party/cgal-data/data/meshes
mkdir -p "$inputs"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
levels="2 3"
[ "${1:-}" = --no-large ] || levels="2 3 5"
for l in $levels; do
  [ -s "$inputs/bunny_loop$l.ply" ] || "$bench" --loop "$data/bunny00.off" "$l" "$inputs/bunny_loop$l.ply" >&2
done
[ -s "$inputs/terrain_noise1025.ply" ] || "$bench" --streamed-terrain 1025 "$inputs/terrain_noise1025.ply"
# Held out of the tuning: a different real mesh, a different terrain generator.
[ -s "$inputs/elephant_loop2.ply" ] || "$bench" --loop "$data/refined_elephant.off" 2 "$inputs/elephant_loop2.ply" >&2
[ -s "$inputs/terrain_ds10.ply" ] || "$bench" --terrain 10 "$inputs/terrain_ds10.ply" >&2
big=$inputs/terrain_12300.ply # 302 M faces, 5.7 GB: made when the large runs are asked for
[ "${1:-}" = --no-large ] || [ -s "$big" ] || "$bench" --streamed-terrain 12300 "$big"
json_num() { grep -oE "\"$2\":[0-9.eE+-]+" "$1" | head -n 1 | cut -d: -f2; }
out=$top/bench/TILED.md
{
echo "# Tiled, out-of-core runs"
echo
echo "\`scripts/bench_tiled.sh\`, $(date -u +%F), $(nproc) cores ($(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -n 1)), $(awk '/MemTotal/ { printf "%.0f GiB", $2 / 1048576 }' /proc/meminfo)."
echo
echo "## Quality: tiled against in core"
echo
echo "Tiles cut for a budget of an eighth of the in-core CLI's need (faces × 110 B ÷ 8), so 100 to 250 tiles. Errors: symmetric surface distance, % of the diagonal, 200 000 samples a side. Tuned on: the bunnies and the noise terrain (the tiles' share of the last level was chosen on them at 1 %); held out: the elephant and the diamond-square terrain."
echo
echo "| mesh | ratio | faces in core / tiled | tiles at level 1, levels | mean error in core / tiled | max error in core / tiled |"
echo "|---|---|---|---|---|---|"
for name in bunny_loop2 bunny_loop3 terrain_noise1025 elephant_loop2 terrain_ds10; do
  mesh=$inputs/$name.ply
  faces=$("$bench" --info "$mesh" | cut -d' ' -f1)
  budget=$(( faces * 110 / 8 ))
  case $name in elephant*|terrain_ds*) label="$name, held out" ;; *) label=$name ;; esac
  for ratio in 0.1 0.01; do
    "$bin" "$mesh" "$work/core.ply" --ratio "$ratio" --json --quiet >"$work/core.json"
    "$bin" "$mesh" "$work/tiled.ply" --ratio "$ratio" --memory "$budget" --json --progress >"$work/tiled.json" 2>"$work/tiled.log"
    read -r cmax cmean _ < <("$bench" --compare "$mesh" "$work/core.ply" --samples 200000)
    read -r tmax tmean _ < <("$bench" --compare "$mesh" "$work/tiled.ply" --samples 200000)
    tiles=$(sed -n 's/^level 1: [0-9]* faces in \([0-9]*\) tiles.*/\1/p' "$work/tiled.log")
    awk -v m="$label ($faces)" -v r="$ratio" -v cf="$(json_num "$work/core.json" output_faces)" \
      -v tf="$(json_num "$work/tiled.json" output_faces)" -v t="$tiles" -v lv="$(json_num "$work/tiled.json" levels)" \
      -v a="$cmean" -v b="$tmean" -v c="$cmax" -v d="$tmax" 'BEGIN {
        printf "| %s | %s | %d / %d (%+.2f %%) | %s, %d | %.5f / %.5f (%+.1f %%) | %.4f / %.4f (%+.1f %%) |\n",
          m, r, cf, tf, 100 * (tf / cf - 1), t, lv, 100 * a, 100 * b, 100 * (b / a - 1), 100 * c, 100 * d, 100 * (d / c - 1) }'
  done
done
if [ "${1:-}" != --no-large ]; then
  mesh=$inputs/bunny_loop5.ply
  echo
  echo "## Memory and time at 77 M faces"
  echo
  echo "bunny00 Loop-subdivided five times ($("$bench" --info "$mesh" | cut -d' ' -f1) faces, $(du -h "$mesh" | cut -f1) binary PLY) to 1 %. Peak: resident memory summed over every process of the run, sampled every 50 ms."
  echo
  echo "| run | faces | peak memory, all processes | wall time |"
  echo "|---|---|---|---|"
  for run in "in core (2 threads)|" "--memory 2G, 2 workers|--memory 2G --workers 2" "--memory 2G, 1 worker|--memory 2G --workers 1"; do
    IFS='|' read -r label args <<<"$run"
    # shellcheck disable=SC2086
    read -r peak seconds code < <(python3 "$top/bench/tree_memory.py" "$bin" "$mesh" "$work/big.ply" --ratio 0.01 --quiet --json $args | tail -n 1)
    faces=$(awk '/^element face/ { print $3; exit }' "$work/big.ply")
    echo "| $label | $faces | $peak MB | $seconds s |"
  done
  echo
  echo "## Beyond memory: $("$bench" --info "$big" | cut -d' ' -f1) faces"
  echo
  echo "A noise terrain of 12300 × 12300 vertices ($(du -h "$big" | cut -f1) binary PLY, written a row at a time by \`vrs_bench --streamed-terrain\`) to 1 % within 4 GB, on 2 worker processes; in core it would need about 33 GB (faces × 110 B)."
  echo
  echo "| run | faces | peak memory, all processes | wall time | work directory at its largest |"
  echo "|---|---|---|---|---|"
  read -r peak seconds code < <(python3 "$top/bench/tree_memory.py" --disk "$work/wd" "$bin" "$big" "$work/big.ply" \
    --ratio 0.01 --quiet --json --memory 4G --workers 2 --work-dir "$work/wd" | tail -n 1)
  faces=$(awk '/^element face/ { print $3; exit }' "$work/big.ply")
  echo "| --memory 4G, 2 workers | $faces | $peak MB | $seconds s | $(cat "$work/wd.peak") MB |"
fi
} | tee "$out"
