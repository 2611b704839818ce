#!/usr/bin/env bash
# Levels of detail in one .glb, side by side in one run (bench/LODS.md): a chain 100/50/10/1 %
# of bunny00 Loop-subdivided to 1.2 M faces and of a textured scan (the refined elephant
# Loop-subdivided to 5.7 M faces, 7 UV charts: bench/attributed_mesh.py), against the
# full-resolution mesh written alone and the levels as separate runs make them (one .glb each,
# its own vertices); each nested level's mean and max error (vrs_bench --compare, read back
# from the file) against a standalone run at the same ratio; and the browser's view: the viewer
# page in headless Chromium, served throttled, draws the coarsest level after how many bytes
# (tests/web/browser_test.mjs). Then the same compressed (--compress: EXT_meshopt_compression,
# lossless), beside meshoptimizer's gltfpack (npm, pinned in web/package.json) compressing the
# full mesh at each ratio (-cc -kv -si R: its own simplifier, one file a level, every vertex
# attribute kept: without -kv it drops the texture coordinates), with its default
# quantization (lossy positions) and without (-noq).
#   scripts/bench_lods.sh [--samples S]      (data: bench/lods.jsonl; the report: bench/lods_report.py)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
samples=100000
[ "${1:-}" = --samples ] && samples=$2
. "$top/scripts/lib/bench_setup.sh" >/dev/null
bin=$top/build/bin/vrsimplify
python=${VRS_CACHE:-/var/cache/vrsimplify}/venv/bin/python
"$top/scripts/lib/bench_inputs.sh" "$bench" "$python" >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ratios="0.5 0.1 0.01"
results=$work/results.jsonl
for name in bunny_loop2 elephant_textured; do
  in=$inputs/$name.ply
  echo "bench_lods: $name" >&2
  /usr/bin/time -f "%e %M" -o "$work/time" "$bin" "$in" "$work/$name-chain.glb" --lods 1,0.5,0.1,0.01 --json >"$work/$name-chain.json"
  read -r seconds kb <"$work/time"
  "$bin" "$in" "$work/$name-full.glb" --ratio 1 --json >"$work/$name-full.json"
  node "$top/tests/web/validate_glb.mjs" "$work/$name-chain.glb" "$work/$name-full.glb" >"$work/$name-validator.txt" ||
    { cat "$work/$name-validator.txt" >&2; exit 1; }
  "$python" "$top/bench/glb_levels.py" "$work/$name-chain.glb" "$work/$name-nested"
  k=1
  for r in $ratios; do
    "$bin" "$in" "$work/$name-alone-$r.glb" --ratio "$r" --json >"$work/$name-alone-$r.json"
    "$python" "$top/bench/glb_levels.py" "$work/$name-alone-$r.glb" "$work/$name-alone-$r-"
    nested=$("$bench" --compare "$in" "$work/$name-nested$k.ply" --samples "$samples")
    alone=$("$bench" --compare "$in" "$work/$name-alone-$r-0.ply" --samples "$samples")
    echo "{\"mesh\":\"$name\",\"ratio\":$r,\"nested\":\"$nested\",\"alone\":\"$alone\",\"alone_bytes\":$(stat -c %s "$work/$name-alone-$r.glb")}" >>"$results"
    k=$((k + 1))
  done
  echo "{\"mesh\":\"$name\",\"chain\":$(tr -d '\n' <"$work/$name-chain.json"),\"full\":$(cat "$work/$name-full.json"),\"seconds\":$seconds,\"peak_kb\":$kb,\"validator\":\"$(head -n 1 "$work/$name-validator.txt" | sed 's/.*: //')\"}" >>"$results"
  # The browser: the coarsest level after how many bytes, throttled to 20 MB/s.
  VRS_PYTHON=$python node "$top/tests/web/browser_test.mjs" "$top/python/vrsimplify/serve.py" \
    "$work/$name-chain.glb" "$work/browser-$name" --throttle 20000000 --max-first 0.02 --stream-only >"$work/browser-$name.txt" || true
  echo "{\"mesh\":\"$name\",\"browser\":$("$python" -c 'import json, sys; print(json.dumps(json.load(open(sys.argv[1]))))' "$work/browser-$name/figures.json"),\"browser_checks\":\"$(grep -c '^ok' "$work/browser-$name.txt") ok, $(grep -c '^FAIL' "$work/browser-$name.txt") failed\"}" >>"$results"

  # Compressed: the chain, the full mesh alone, the separate levels; gltfpack beside.
  echo "bench_lods: $name compressed" >&2
  /usr/bin/time -f "%e %M" -o "$work/time" "$bin" "$in" "$work/$name-chain-c.glb" --lods 1,0.5,0.1,0.01 --compress --json >"$work/$name-chain-c.json"
  read -r cseconds ckb <"$work/time"
  "$bin" "$in" "$work/$name-full-c.glb" --ratio 1 --compress --json >/dev/null
  node "$top/tests/web/validate_glb.mjs" "$work/$name-chain-c.glb" >"$work/$name-validator-c.txt" ||
    { cat "$work/$name-validator-c.txt" >&2; exit 1; }
  node "$top/tests/web/glb_decoded.mjs" "$work/$name-chain.glb" "$work/$name-chain-c.glb" >&2
  sizes="" gp="" gpq=""
  for r in 0.5 0.1 0.01; do
    "$bin" "$in" "$work/$name-alone-c-$r.glb" --ratio "$r" --compress --json >/dev/null
    sizes+="\"$r\":$(stat -c %s "$work/$name-alone-c-$r.glb"),"
  done
  for r in 1 0.5 0.1 0.01; do
    si=(); [ "$r" = 1 ] || si=(-si "$r")
    "$top/web/node_modules/.bin/gltfpack" -i "$work/$name-full.glb" -o "$work/$name-gp-$r.glb" -cc -kv "${si[@]}" >/dev/null 2>&1
    "$top/web/node_modules/.bin/gltfpack" -i "$work/$name-full.glb" -o "$work/$name-gpnoq-$r.glb" -cc -noq -kv "${si[@]}" >/dev/null 2>&1
    gp+="\"$r\":$(stat -c %s "$work/$name-gp-$r.glb"),"
    gpq+="\"$r\":$(stat -c %s "$work/$name-gpnoq-$r.glb"),"
  done
  VRS_PYTHON=$python node "$top/tests/web/browser_test.mjs" "$top/python/vrsimplify/serve.py" \
    "$work/$name-chain-c.glb" "$work/browser-c-$name" --throttle 20000000 --max-first 0.02 --stream-only >"$work/browser-c-$name.txt" || true
  echo "{\"mesh\":\"$name\",\"compressed\":{\"chain\":$(tr -d '\n' <"$work/$name-chain-c.json"),\"full\":$(stat -c %s "$work/$name-full-c.glb"),\"alone\":{${sizes%,}},\"gltfpack\":{${gp%,}},\"gltfpack_noq\":{${gpq%,}},\"seconds\":$cseconds,\"peak_kb\":$ckb,\"validator\":\"$(head -n 1 "$work/$name-validator-c.txt" | sed 's/.*: //')\",\"browser\":$("$python" -c 'import json, sys; print(json.dumps(json.load(open(sys.argv[1]))))' "$work/browser-c-$name/figures.json"),\"browser_checks\":\"$(grep -c '^ok' "$work/browser-c-$name.txt") ok, $(grep -c '^FAIL' "$work/browser-c-$name.txt") failed\"}}" >>"$results"
done
cp "$results" "$top/bench/lods.jsonl"
"$python" "$top/bench/lods_report.py" "$top/bench/lods.jsonl" "$top/bench/LODS.md"
echo "wrote bench/lods.jsonl and bench/LODS.md" >&2
