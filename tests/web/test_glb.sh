#!/usr/bin/env bash
# Levels of detail and progressive meshes in one .glb, from the command line to the browser: every file Khronos'
# glTF-Validator passes with no error and no warning (an untextured scan, a textured OBJ whose
# image lies in another folder, a colored PLY); the levels nest and each is drawn from a prefix
# of the shared vertices; what cannot be written is refused with one line and no file; then
# the viewer page, served throttled by vrsimplify serve, in headless Chromium
# (tests/web/browser_test.mjs).
#   test_glb.sh VRSIMPLIFY PYTHON CGAL_DATA OUT_DIR
set -u
bin=$1 python=$2 data=$3 out=$4
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
rm -rf "$out" && mkdir -p "$out/tex/sub"
[ -d "$top/web/node_modules/gltf-validator" ] || { echo "web/node_modules missing: run scripts/setup.sh"; exit 1; }
failed=0
fail() { failed=$((failed + 1)); echo "FAIL: $1"; }
validate() { node "$here/validate_glb.mjs" "$@" || fail "glTF-Validator: $*"; }

# An untextured scan, four nested levels.
"$bin" "$data/elephant.off" "$out/elephant.glb" --lods 1,0.5,0.1,0.01 --json >"$out/elephant.json" ||
  fail "elephant --lods"
validate "$out/elephant.glb"
"$python" - "$out/elephant.json" <<'PY' || fail "elephant's levels"
import json, sys
r = json.load(open(sys.argv[1]))
lv = r["levels"]
assert [l["ratio"] for l in lv] == [1, 0.5, 0.1, 0.01], lv
assert lv[0]["faces"] == r["input_faces"], "ratio 1 is the input"
assert all(a["vertices"] > b["vertices"] for a, b in zip(lv, lv[1:])), "nested prefixes"
assert all(a["bytes_to_draw"] > b["bytes_to_draw"] for a, b in zip(lv, lv[1:]))
assert lv[-1]["bytes_to_draw"] < 0.1 * r["file_bytes"], lv[-1]
PY

# A textured OBJ (two charts, per-corner texture coordinates) with its image one folder up
# from the output, and a halving chain.
"$python" "$top/tests/textured/textured_mesh.py" make "$data/bunny00.off" "$out/tex/bunny.obj" 1 >/dev/null
convert -size 64x64 gradient:orange-navy "$out/tex/bunny.png"
printf 'newmtl skin\nmap_Kd bunny.png\n' >"$out/tex/bunny.mtl"
sed -i '1i mtllib bunny.mtl\nusemtl skin' "$out/tex/bunny.obj"
"$bin" "$out/tex/bunny.obj" "$out/tex/sub/bunny.glb" --lods 4 >"$out/bunny.txt" || fail "textured --lods 4"
validate "$out/tex/sub/bunny.glb"
grep -q '"uri":"../bunny.png"' "$out/tex/sub/bunny.glb" || fail "the texture's URI relative to the .glb"
grep -q "4 levels" "$out/bunny.txt" || fail "a halving chain of 4: $(cat "$out/bunny.txt")"

# Compressed (EXT_meshopt_compression): the same levels, the same vertices bit for bit once
# decoded (tests/web/glb_decoded.mjs, with meshoptimizer's own decoder from three.js), each
# coarser level decodable from the first bytes of the vertex stream, and smaller.
"$bin" "$data/elephant.off" "$out/elephant-c.glb" --lods 1,0.5,0.1,0.01 --compress --json >"$out/elephant-c.json" ||
  fail "elephant --lods --compress"
validate "$out/elephant-c.glb"
grep -q '"extensionsRequired":\["EXT_meshopt_compression"\]' "$out/elephant-c.glb" || fail "compressed: the extension required"
node "$here/glb_decoded.mjs" "$out/elephant.glb" "$out/elephant-c.glb" || fail "compressed elephant decodes to the uncompressed levels"
"$bin" "$out/tex/bunny.obj" "$out/tex/sub/bunny-c.glb" --lods 4 --compress >/dev/null || fail "textured --lods 4 --compress"
validate "$out/tex/sub/bunny-c.glb"
node "$here/glb_decoded.mjs" "$out/tex/sub/bunny.glb" "$out/tex/sub/bunny-c.glb" || fail "compressed bunny decodes to the uncompressed levels"
[ "$(stat -c %s "$out/elephant-c.glb")" -lt "$(( $(stat -c %s "$out/elephant.glb") * 3 / 4 ))" ] ||
  fail "compression saves a quarter at least"
refuse_compress_other() {
  "$bin" "$data/elephant.off" "$out/x.ply" --compress >/dev/null 2>"$out/refusal.err"
  [ $? -eq 2 ] && grep -q -- --compress "$out/refusal.err" && [ ! -e "$out/x.ply" ] || fail "--compress with a .ply output"
}
refuse_compress_other

# A colored PLY, one level (a plain .glb output).
bash "$top/tests/support/colored_ply.sh" "$data/fandisk.off" "$out/fandisk.ply"
"$bin" "$out/fandisk.ply" "$out/fandisk.glb" --ratio 0.2 >/dev/null || fail "colored .glb"
validate "$out/fandisk.glb"
grep -q '"COLOR_0"' "$out/fandisk.glb" || fail "the colors in the .glb"
grep -q 'MSFT_lod' "$out/fandisk.glb" && fail "one level needs no MSFT_lod"

# A progressive file (--progressive): the validator passes it, with its extension declared and
# not required; refusals of what it cannot hold.
"$bin" "$data/elephant.off" "$out/elephant-p.glb" --progressive >/dev/null || fail "elephant --progressive"
validate "$out/elephant-p.glb"
grep -q '"extensionsUsed":\["VRS_mesh_progressive"\]' "$out/elephant-p.glb" || fail "progressive: the extension declared"
grep -q 'extensionsRequired' "$out/elephant-p.glb" && fail "progressive: no extension required"
"$bin" "$out/tex/bunny.obj" "$out/tex/sub/bunny-p.glb" --progressive >/dev/null || fail "textured --progressive"
validate "$out/tex/sub/bunny-p.glb"
grep -q '"uri":"../bunny.png"' "$out/tex/sub/bunny-p.glb" || fail "progressive: the texture's URI"
# The browser's decoder (tests/web/progressive_decoded.mjs, in Node) rebuilds each full mesh
# bit for bit, fed whole or in pieces: plain, textured (seams), colored.
decoded() { # input progressive.glb full.glb
  "$bin" "$1" "$3" --lods 1 >/dev/null && node "$here/progressive_decoded.mjs" "$2" "$3" >/dev/null ||
    fail "progressive: $2 decodes to the full mesh"
}
decoded "$data/elephant.off" "$out/elephant-p.glb" "$out/elephant-full.glb"
decoded "$out/tex/bunny.obj" "$out/tex/sub/bunny-p.glb" "$out/tex/sub/bunny-full.glb"
"$bin" "$out/fandisk.ply" "$out/fandisk-p.glb" --progressive >/dev/null || fail "colored --progressive"
decoded "$out/fandisk.ply" "$out/fandisk-p.glb" "$out/fandisk-full.glb"

# Refusals: one line, exit 2 (usage) or 1, no file.
refuse() { # expected-exit output args...
  local code=$1 target=$2
  shift 2
  "$bin" "$@" >/dev/null 2>"$out/refusal.err"
  local got=$?
  [ $got -eq "$code" ] && [ "$(wc -l <"$out/refusal.err")" -eq 1 ] && [ ! -e "$target" ] ||
    fail "refusal of '$*': exit $got, $(cat "$out/refusal.err")"
}
refuse 2 "$out/x.ply" "$data/elephant.off" "$out/x.ply" --lods 0.5,0.1
refuse 2 "$out/x.glb" "$data/elephant.off" "$out/x.glb" --lods 0.5,0
refuse 2 "$out/x.glb" "$data/elephant.off" "$out/x.glb" --lods 1.5
refuse 2 "$out/x.glb" "$data/elephant.off" "$out/x.glb" --lods abc
refuse 2 "$out/x.glb" "$data/elephant.off" "$out/x.glb" --faces 100
refuse 2 "$out/x.glb" "$data/elephant.off" "$out/x.glb" --lods 3 --memory 1M
refuse 2 "$out/x.glb" "$data/elephant.off" "$out/x.glb" --lods 3 --ascii
refuse 2 "$out/x.glb" "$data/elephant.off" "$out/x.glb" --progressive --lods 3
refuse 2 "$out/x.glb" "$data/elephant.off" "$out/x.glb" --progressive --compress
refuse 2 "$out/x.glb" "$data/elephant.off" "$out/x.glb" --progressive --base 2
refuse 2 "$out/x.ply" "$data/elephant.off" "$out/x.ply" --progressive
# Several texture images: one material per .glb.
cp /usr/share/assimp/models/OBJ/spider.obj /usr/share/assimp/models/OBJ/spider.mtl "$out/"
refuse 1 "$out/spider.glb" "$out/spider.obj" "$out/spider.glb" --lods 2
# A vertex with NaN coordinates on a face: glTF has no place for it.
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\nnan 1 0\n0 1 1\n3 0 1 2\n3 0 2 3\n' >"$out/nan.off"
refuse 1 "$out/nan.glb" "$out/nan.off" "$out/nan.glb" --ratio 1
ls "$out"/.vrsimplify-* >/dev/null 2>&1 && fail "a temporary file was left behind"

# The page in a real browser, throttled: the textured chain and the scan.
export VRS_PYTHON=$python
# Served from beside its texture: the server hands out only what lies in the .glb's folder.
"$bin" "$out/tex/bunny.obj" "$out/tex/bunny.glb" --lods 4 >/dev/null || fail "textured --lods 4 beside its texture"
"$bin" "$out/tex/bunny.obj" "$out/tex/bunny-c.glb" --lods 4 --compress >/dev/null ||
  fail "textured --lods 4 --compress beside its texture"
node "$here/browser_test.mjs" "$top/python/vrsimplify/serve.py" "$out/tex/bunny.glb" \
  "$out/browser-bunny" --throttle 1000000 --max-first 0.2 || fail "browser: textured bunny"
node "$here/browser_test.mjs" "$top/python/vrsimplify/serve.py" "$out/elephant.glb" \
  "$out/browser-elephant" --throttle 300000 --max-first 0.1 || fail "browser: elephant"
node "$here/browser_test.mjs" "$top/python/vrsimplify/serve.py" "$out/tex/bunny-c.glb" \
  "$out/browser-bunny-c" --throttle 300000 --max-first 0.3 || fail "browser: compressed textured bunny"
node "$here/browser_test.mjs" "$top/python/vrsimplify/serve.py" "$out/elephant-c.glb" \
  "$out/browser-elephant-c" --throttle 100000 --max-first 0.15 || fail "browser: compressed elephant"
# The progressive textured bunny beside its texture: base first, refined as the bytes arrive,
# each prefix as GLTFLoader draws it with the plugin.
"$bin" "$out/tex/bunny.obj" "$out/tex/bunny-p.glb" --progressive >/dev/null || fail "textured --progressive beside its texture"
node "$here/progressive_test.mjs" "$top/python/vrsimplify/serve.py" "$out/tex/bunny-p.glb" \
  "$out/browser-bunny-p" --throttle 500000 --max-first 0.25 || fail "browser: progressive textured bunny"

echo "$failed failed"
[ "$failed" -eq 0 ]
