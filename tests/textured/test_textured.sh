#!/usr/bin/env bash
# Textured meshes through a host: per-corner texture coordinates must come out on every face,
# each corner with a value its vertex had, all three from one input chart (textured_mesh.py
# check). Inputs: bunny00 with synthetic charts as PLY (per-face texcoord lists) and OBJ (vt
# indices), pymeshlab's textured bunny (a real UV atlas) and assimp's real textured OBJ files
# (in core). The check is first shown to fail on a
# corrupted output, so a pass means something.
#   test_textured.sh cli VRSIMPLIFY PYTHON CGAL_DATA OUT_DIR
#   test_textured.sh tiled VRSIMPLIFY PYTHON CGAL_DATA OUT_DIR   (--memory 1M: ~200 tiles)
#   test_textured.sh meshlabserver REPO_ROOT PYTHON CGAL_DATA OUT_DIR   (MeshLab 2020.09)
set -u
mode=$1 tool=$2 python=$3 cgal=$4 out=$(realpath -m "$5")
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out" && mkdir -p "$out"
passed=0 failed=0
check() { if eval "$1"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $2"; fi; }
make_mesh() { "$python" "$here/textured_mesh.py" make "$cgal/bunny00.off" "$1" 2 >/dev/null; }
verify() { "$python" "$here/textured_mesh.py" check "$1" "$2"; }

make_mesh "$out/bunny_charts.ply" && make_mesh "$out/bunny_charts.obj"
inputs=("$out/bunny_charts.ply" "$out/bunny_charts.obj")
# A real textured OBJ of 10 k faces with its UV atlas (pymeshlab's own sample, in the wheel):
# in tiles of 1 MB it runs six levels, each cutting the charts anew.
atlas=$("$python" -c 'import os, pymeshlab; print(os.path.join(os.path.dirname(pymeshlab.__file__), "tests", "sample_meshes", "bunny10k_textured.obj"))')
[ -f "$atlas" ] && cp "$atlas" "${atlas%.obj}.mtl" "$out/" 2>/dev/null
[ "$mode" = meshlabserver ] || inputs+=("$out/bunny10k_textured.obj")
case "$mode" in
  cli)
    inputs+=(/usr/share/assimp/models/OBJ/regr01.obj /usr/share/assimp/models/OBJ/spider.obj)
    simplify() { "$tool" "$1" "$2" --ratio "$3" --json >"$2.json"; }
    ;;
  tiled)
    simplify() {
      "$tool" "$1" "$2" --ratio "$3" --memory 1M --json >"$2.json" && grep -q '"tiled":true' "$2.json"
    }
    ;;
  meshlabserver)
    # MeshLab 2020.09's own OBJ reader aborts on OBJ files with texture coordinates (an
    # assertion in vcglib's importer): only the PLY goes through it.
    inputs=("$out/bunny_charts.ply")
    ml=$("$tool/scripts/meshlab_private.sh" "$out/meshlab") || exit 1
    source "$tool/scripts/mlx.sh"
    simplify() {
      { mlx_begin; mlx_vertex_removal TargetPerc="$3" TargetFaceNum=0; mlx_end; } >"$out/run.mlx"
      (cd "$out" && LD_LIBRARY_PATH=/usr/lib/x86_64-linux-gnu/meshlab "$here/../../scripts/lib/on_display.sh" \
        "$ml/meshlabserver" -i "$1" -o "$2" -m wt -s "$out/run.mlx" >"$2.log" 2>&1)
    }
    ;;
  *) echo "usage: test_textured.sh cli|tiled|meshlabserver ..."; exit 2 ;;
esac

for input in "${inputs[@]}"; do
  name=$(basename "$input")
  for ratio in 0.5 0.2 0.1; do
    result="$out/${name%.*}-$ratio.${name##*.}"
    check 'simplify "$input" "$result" "$ratio" && [ -s "$result" ]' "$name at $ratio: no output"
    check 'verify "$input" "$result"' "$name at $ratio: corners lost their texture coordinates"
  done
done
# The check can fail: one corner of the first face moved to another chart's value.
"$python" - "$out/bunny_charts-0.1.ply" "$out/corrupt.ply" <<'PY'
import sys, pymeshlab
ms = pymeshlab.MeshSet(); ms.load_new_mesh(sys.argv[1]); m = ms.current_mesh()
w = m.wedge_tex_coord_matrix().copy(); w[0, 0] += 2.0
ms.add_mesh(pymeshlab.Mesh(vertex_matrix=m.vertex_matrix(), face_matrix=m.face_matrix(),
                           w_tex_coords_matrix=w))
ms.save_current_mesh(sys.argv[2])
PY
check '[ -s "$out/corrupt.ply" ] && ! verify "$out/bunny_charts.ply" "$out/corrupt.ply" >/dev/null' "the check passed a corrupted output"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
