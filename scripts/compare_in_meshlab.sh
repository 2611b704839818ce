#!/usr/bin/env bash
# Our filter and MeshLab's Quadric Edge Collapse Decimation on the same mesh and target, inside
# the real meshlabserver, measured by MeshLab's own Hausdorff Distance filter.
#   scripts/compare_in_meshlab.sh MESH [RATIO] [OUT_DIR]     (plugin built, meshlab installed)
# Time per run: K copies of the mesh are simplified in one meshlabserver call, minus a call that
# only loads them, divided by K (meshlabserver itself times nothing). Best of 3.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
mesh=$(realpath "$1")
ratio=${2:-0.1}
out=$(realpath -m "${3:-$top/out}")
name=$(basename "${mesh%.*}")
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# shellcheck source=mlx.sh
source "$top/scripts/mlx.sh"
ml=$("$top/scripts/meshlab_private.sh" "$work/meshlab")
server() { # args...: runs the private meshlabserver, log to $work/log
  (cd "$work" && LD_LIBRARY_PATH=/usr/lib/x86_64-linux-gnu/meshlab \
    "$top/scripts/lib/on_display.sh" "$ml/meshlabserver" "$@" >"$work/log" 2>&1) || {
    echo "meshlabserver failed ($*):" >&2; tail -20 "$work/log" >&2; return 1; }
}
faces=$(awk 'NF && $1 !~ /^#/ { n++; if (n == 2) { print $2; exit } }' "$mesh")
case "$mesh" in *.off) ;; *) echo "compare_in_meshlab: give an OFF mesh" >&2; exit 2 ;; esac
target=$(awk -v f="$faces" -v r="$ratio" 'BEGIN { printf "%d", f * r + 0.5 }')

K=5
inputs=(); for _ in $(seq $K); do inputs+=(-i "$mesh"); done
{ mlx_begin; mlx_end; } >"$work/none.mlx"
for method in ours qecd; do
  { mlx_begin
    for layer in $(seq 0 $((K - 1))); do
      mlx_select_layer "$layer"
      if [ $method = ours ]; then mlx_vertex_removal TargetFaceNum="$target"; else mlx_qecd TargetFaceNum="$target"; fi
    done
    mlx_end; } >"$work/$method.mlx"
done
now() { date +%s.%N; }
declare -A best=([none]=999 [ours]=999 [qecd]=999)
for _ in 1 2 3; do
  for method in none ours qecd; do
    t0=$(now); server "${inputs[@]}" -s "$work/$method.mlx"; t1=$(now)
    best[$method]=$(awk -v a="$t0" -v b="$t1" -v m="${best[$method]}" 'BEGIN { d = b - a; print (d < m ? d : m) }')
  done
done

# One more call each to save the result, then one to measure both against the original.
for method in ours qecd; do
  { mlx_begin
    if [ $method = ours ]; then mlx_vertex_removal TargetFaceNum="$target"; else mlx_qecd TargetFaceNum="$target"; fi
    mlx_end; } >"$work/save-$method.mlx"
  server -i "$mesh" -o "$out/$name-$method.ply" -m vc vn -s "$work/save-$method.mlx"
  [ -s "$out/$name-$method.ply" ] || { echo "no output for $method" >&2; exit 1; }
done
{ mlx_begin
  for pair in "1 0" "0 1" "2 0" "0 2"; do
    read -r a b <<<"$pair"; mlx_hausdorff SampledMesh="$a" TargetMesh="$b"
  done
  mlx_end; } >"$work/hausdorff.mlx"
server -i "$mesh" -i "$out/$name-ours.ply" -i "$out/$name-qecd.ply" -s "$work/hausdorff.mlx"
cp "$work/log" "$out/$name-hausdorff.log"
# Each Hausdorff run logs "LOG: 2 Values w.r.t. BBox Diag" then "LOG: 2 min : a max b mean : c"
# (meshlabserver also reprints the whole log after each filter, without the LOG prefix).
mapfile -t rel < <(awk '/^LOG: [0-9]+ Values w.r.t. BBox Diag/ { getline; print $7, $10 }' "$work/log")
[ ${#rel[@]} -eq 4 ] || { echo "Hausdorff results not found in the log" >&2; exit 1; }
sym() { # two "max mean" lines -> symmetric max and mean, in % of the bbox diagonal
  awk -v a="$1" -v b="$2" 'BEGIN { split(a, x, " "); split(b, y, " ");
    printf "%.4f %.4f", 100 * (x[1] > y[1] ? x[1] : y[1]), 100 * (x[2] + y[2]) / 2 }'
}
read -r ours_max ours_mean <<<"$(sym "${rel[0]}" "${rel[1]}")"
read -r qecd_max qecd_mean <<<"$(sym "${rel[2]}" "${rel[3]}")"
ply_faces() { awk '/^element face/ { print $3; exit }' "$1"; }
per_run() { awk -v a="${best[$1]}" -v b="${best[none]}" -v k=$K 'BEGIN { d = (a - b) / k; printf "%.3f", d < 0 ? 0 : d }'; }

echo
echo "$name: $faces faces -> target $target (ratio $ratio), in meshlabserver (MeshLab 2020.09)"
row() { printf '| %-42s | %5s | %8s | %21s | %22s |\n' "$@"; }
row method faces "time (s)" "Hausdorff max (%diag)" "Hausdorff mean (%diag)"
row "$(printf -- '-%.0s' {1..42})" ----- -------- "$(printf -- '-%.0s' {1..21})" "$(printf -- '-%.0s' {1..22})"
row "Vertex Removal Decimation (this plugin)" "$(ply_faces "$out/$name-ours.ply")" "$(per_run ours)" "$ours_max" "$ours_mean"
row "Quadric Edge Collapse Decimation (MeshLab)" "$(ply_faces "$out/$name-qecd.ply")" "$(per_run qecd)" "$qecd_max" "$qecd_mean"
echo
echo "Outputs: $out/$name-ours.ply, $out/$name-qecd.ply (MeshLab's log: $out/$name-hausdorff.log)"
echo "Hausdorff: symmetric (max of both directions, mean of both means), MeshLab's 'Hausdorff Distance' filter."
