#!/usr/bin/env bash
# Tiled runs keep every attribute, at scale: the refined elephant Loop-subdivided three times
# (5.7 M faces) with 7 UV charts (per-corner texcoord lists) and, apart, as a georeferenced
# colored scan (double coordinates at UTM magnitudes, a color and a quality per vertex)
# (bench/attributed_mesh.py), at 10 % and 1 %, in core and with --memory at an eighth of the
# in-core run's peak: every output corner's (vertex, u, v) an input corner's, every vertex record
# bit for bit an input's, faces, mean/max error (vrs_bench --compare) and peak memory summed
# over every process (bench/tree_memory.py). Writes bench/TILED_ATTRIBUTES.md.
#   scripts/bench_tiled_attributes.sh
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/scripts/setup.sh" >/dev/null
"$top/scripts/build.sh" >/dev/null
bin=$top/build/bin/vrsimplify bench=$top/build/bin/vrs_bench python=${VRS_CACHE:-/var/cache/vrsimplify}/venv/bin/python
inputs=$top/third_party/bench-inputs data=$top/third_party/cgal-data/data/meshes
mkdir -p "$inputs"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
base=$inputs/elephant_loop3.ply
[ -s "$base" ] || "$bench" --loop "$data/refined_elephant.off" 3 "$base" >&2
for kind in textured colored; do
  [ -s "$inputs/elephant_$kind.ply" ] || "$python" "$top/bench/attributed_mesh.py" "$kind" "$base" "$inputs/elephant_$kind.ply" >&2
done
json_num() { grep -oE "\"$2\":[0-9.eE+-]+" "$1" | head -n 1 | cut -d: -f2; }
# The check can fail: one byte of the first vertex changed is found.
"$bin" "$inputs/elephant_colored.ply" "$work/c.ply" --ratio 0.01 --memory 64M --quiet >/dev/null
"$python" - "$work/c.ply" <<'PY'
import sys
data = bytearray(open(sys.argv[1], "rb").read())
data[data.index(b"end_header\n") + 11 + 2] ^= 1
open(sys.argv[1], "wb").write(data)
PY
if "$python" "$top/bench/attributed_mesh.py" check "$inputs/elephant_colored.ply" "$work/c.ply" >/dev/null; then
  echo "bench_tiled_attributes: the check passed a corrupted output" >&2
  exit 1
fi
out=$top/bench/TILED_ATTRIBUTES.md
{
echo "# Tiled runs keep every attribute"
echo
echo "\`scripts/bench_tiled_attributes.sh\`, $(date -u +%F), $(nproc) cores, $(awk '/MemTotal/ { printf "%.0f GiB", $2 / 1048576 }' /proc/meminfo). The refined elephant Loop-subdivided three times, $("$bench" --info "$base" | cut -d' ' -f1) faces: with 7 UV charts as per-corner texcoord lists (binary PLY), and as a georeferenced colored scan (double x, y, z at 500 000 / 4 100 000 m, uchar red green blue, float quality). *Wrong*: output corners whose (vertex, u, v) is no input corner's, or output vertex records that are not an input record byte for byte (the check is first shown to catch one flipped bit). Budget: an eighth of the in-core run's peak. Peak: resident memory summed over every process of the run. Error: symmetric Hausdorff, mean and max, % of the bounding-box diagonal (\`vrs_bench --compare\`)."
echo
echo "| mesh | ratio | run | faces (target) | wrong | mean error | max error | peak memory | budget | wall time |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for kind in textured colored; do
  mesh=$inputs/elephant_$kind.ply
  for ratio in 0.1 0.01; do
    read -r peak seconds code < <("$python" "$top/bench/tree_memory.py" "$bin" "$mesh" "$work/core.ply" --ratio "$ratio" --quiet --json | tail -n 1)
    [ "$code" = 0 ] || { echo "in-core run failed" >&2; exit 1; }
    budget=$(awk -v p="$peak" 'BEGIN { printf "%dM", p / 8 }')
    read -r tpeak tseconds tcode < <("$python" "$top/bench/tree_memory.py" "$bin" "$mesh" "$work/tiled.ply" --ratio "$ratio" --memory "$budget" --json | tail -n 1)
    [ "$tcode" = 0 ] || { echo "tiled run failed" >&2; exit 1; }
    target=$(awk -v r="$ratio" -v f="$("$bench" --info "$mesh" | cut -d' ' -f1)" 'BEGIN { printf "%d", r * f + 0.5 }')
    for run in core tiled; do
      faces=$("$bench" --info "$work/$run.ply" | cut -d' ' -f1)
      check=$("$python" "$top/bench/attributed_mesh.py" check "$mesh" "$work/$run.ply" || true)
      wrong=${check%% *}
      if [[ $check == *"written as"* ]]; then
        # Another vertex layout (float coordinates of a double input): its positions were cut
        # to float steps of 0.25-0.5 m at these magnitudes; no error to measure against.
        echo "| $kind | $ratio | in core | $faces ($target) | all ($wrong): ${check#*: } | – | – | $peak MB | – | $seconds s |"
        continue
      fi
      # Measured in float near the origin: at 4e6 m a float has 0.5 m steps.
      "$python" "$top/bench/attributed_mesh.py" local "$mesh" "$work/in-local.ply"
      "$python" "$top/bench/attributed_mesh.py" local "$work/$run.ply" "$work/out-local.ply"
      read -r emax emean _ < <("$bench" --compare "$work/in-local.ply" "$work/out-local.ply" --samples 200000)
      emax=$(awk -v e="$emax" 'BEGIN { printf "%.4f %%", 100 * e }') emean=$(awk -v e="$emean" 'BEGIN { printf "%.4f %%", 100 * e }')
      if [ $run = core ]; then
        echo "| $kind | $ratio | in core | $faces ($target) | $wrong | $emean | $emax | $peak MB | – | $seconds s |"
      else
        echo "| $kind | $ratio | --memory $budget | $faces ($target) | $wrong | $emean | $emax | $tpeak MB | $budget | $tseconds s |"
      fi
    done
  done
done
} >"$out.tmp"
mv "$out.tmp" "$out"
cat "$out"
