#!/usr/bin/env bash
# A progressive .glb beside the levels of detail and the full mesh alone, one run
# (bench/PROGRESSIVE.md): bunny00 Loop-subdivided to 1.2 M faces and the refined elephant
# Loop-subdivided to 5.7 M faces with 7 UV charts (bench/attributed_mesh.py). For each: the
# file sizes (progressive, full mesh alone, the LOD chain 100/50/10/1 %; each also gzip -9, and
# the full mesh and chain with EXT_meshopt_compression), the bytes the base needs, the mesh
# drawn after 10 % of the file (its records decoded by the reference decoder) against a
# standalone run to the same face count (mean and max error against the input, vrs_bench
# --compare), Khronos' validator, and the browser: the viewer page in headless Chromium,
# served throttled (tests/web/progressive_test.mjs: records a second, longest frame; the whole
# stream for the bunny, the base and the decoder alone for the elephant), and the bunny's
# pictures after 1, 5, 20 and 100 % of its bytes (bench/renders/progressive_bunny.png).
#   scripts/bench_progressive.sh [--samples S] [--only NAME]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
samples=100000 only=""
while [ $# -gt 0 ]; do
  case $1 in
    --samples) samples=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    *) echo "usage: scripts/bench_progressive.sh [--samples S] [--only NAME]" >&2; exit 2 ;;
  esac
done
. "$top/scripts/lib/bench_setup.sh" >/dev/null
bin=$top/build/bin/vrsimplify
python=${VRS_CACHE:-/var/cache/vrsimplify}/venv/bin/python
"$top/scripts/lib/bench_inputs.sh" "$bench" "$python" >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
results=$work/results.jsonl
size() { stat -c %s "$1"; }
gz() { gzip -9 -c "$1" | wc -c; }
for name in bunny_loop2 elephant_textured; do
  [ -z "$only" ] || [ "$only" = "$name" ] || continue
  in=$inputs/$name.ply
  echo "bench_progressive: $name" >&2
  /usr/bin/time -f "%e %M" -o "$work/time" "$bin" "$in" "$work/p.glb" --progressive --json >"$work/p.json"
  read -r seconds kb <"$work/time"
  "$bin" "$in" "$work/full.glb" --lods 1 >/dev/null
  "$bin" "$in" "$work/chain.glb" --lods 1,0.5,0.1,0.01 >/dev/null
  "$bin" "$in" "$work/full-c.glb" --lods 1 --compress >/dev/null
  "$bin" "$in" "$work/chain-c.glb" --lods 1,0.5,0.1,0.01 --compress >/dev/null
  validator=$(node "$top/tests/web/validate_glb.mjs" "$work/p.glb" | head -n 1 | sed 's/.*: //')
  # The mesh drawn after 10 % of the file, against a standalone run to its face count.
  prefix=$("$python" "$top/bench/progressive_prefix.py" "$work/p.glb" 0.1 "$work/prefix.ply")
  faces=$(echo "$prefix" | "$python" -c 'import json, sys; print(json.load(sys.stdin)["faces"])')
  "$bin" "$in" "$work/alone.ply" --faces "$faces" >/dev/null
  drawn=$("$bench" --compare "$in" "$work/prefix.ply" --samples "$samples")
  alone=$("$bench" --compare "$in" "$work/alone.ply" --samples "$samples")
  # The browser, throttled to 20 MB/s.
  # The whole stream for the bunny; the elephant's 5.7 M faces take SwiftShader seconds a
  # frame: its base and the decoder alone.
  mode=--stream-only
  [ "$name" = bunny_loop2 ] || mode=--decoder-only
  VRS_PYTHON=$python node "$top/tests/web/progressive_test.mjs" "$top/python/vrsimplify/serve.py" \
    "$work/p.glb" "$work/browser" --throttle 20000000 --max-first 0.02 $mode >"$work/browser.txt" 2>&1 || true
  echo "{\"mesh\":\"$name\",\"progressive\":$(cat "$work/p.json"),\"seconds\":$seconds,\"peak_kb\":$kb,\
\"bytes\":{\"progressive\":$(size "$work/p.glb"),\"full\":$(size "$work/full.glb"),\"chain\":$(size "$work/chain.glb"),\
\"full_meshopt\":$(size "$work/full-c.glb"),\"chain_meshopt\":$(size "$work/chain-c.glb"),\
\"progressive_gzip\":$(gz "$work/p.glb"),\"full_gzip\":$(gz "$work/full.glb"),\"chain_gzip\":$(gz "$work/chain.glb"),\
\"full_meshopt_gzip\":$(gz "$work/full-c.glb")},\
\"prefix\":$prefix,\"drawn\":\"$drawn\",\"alone\":\"$alone\",\"validator\":\"$validator\",\
\"browser\":$("$python" -c 'import json, sys; print(json.dumps(json.load(open(sys.argv[1]))))' "$work/browser/figures.json"),\
\"browser_checks\":\"$(grep -c '^ok' "$work/browser.txt") ok, $(grep -c '^FAIL' "$work/browser.txt") failed\"}" >>"$results"
  grep '^FAIL' "$work/browser.txt" >&2 || true
  if [ "$name" = bunny_loop2 ]; then # the README's strip: the base, 5, 20 and 100 % of the bytes
    VRS_PYTHON=$python node "$top/tests/web/progressive_pictures.mjs" "$top/python/vrsimplify/serve.py" \
      "$work/p.glb" "$work/pictures" base 0.05 0.2 1 >"$work/pictures.txt"
    strip=()
    while read -r share records faces needed || [ -n "${share:-}" ]; do
      strip+=(-label "$(awk -v n="$needed" -v f="$faces" 'BEGIN { printf "%.3g %%%% of the bytes, %d faces", 100 * n, f }')"
              "$work/pictures/bytes-$share.png")
    done <"$work/pictures.txt"
    montage "${strip[@]}" -tile 4x1 -geometry 240x240+4+4 -background '#20242a' -fill white \
      -font DejaVu-Sans -pointsize 13 "$top/bench/renders/progressive_bunny.png"
  fi
done
if [ -n "$only" ] && [ -s "$top/bench/progressive.jsonl" ]; then # keep the other mesh's line
  grep -v "\"mesh\":\"$only\"" "$top/bench/progressive.jsonl" >>"$results" || true
fi
cp "$results" "$top/bench/progressive.jsonl"
"$python" "$top/bench/progressive_report.py" "$top/bench/progressive.jsonl" "$top/bench/PROGRESSIVE.md"
echo "wrote bench/progressive.jsonl and bench/PROGRESSIVE.md" >&2
