#!/usr/bin/env bash
# The sweep through the real meshlabserver and the plugin, on a representative subset of the
# real meshes (CGAL's awkward ones: holes, non-manifold, several components, slivers; assimp's
# in the formats MeshLab reads, malformed ones included) at 50 %, 10 % and 1 %:
# never a crash in our filter, every output's vertices a subset of what MeshLab loaded, and a
# clear message in the log when the input is unusable.
#   test_meshlabserver_sweep.sh REPO_ROOT CGAL_DATA_DIR OUT_DIR
set -u
top=$(realpath "$1") data=$(realpath "$2") out=$(realpath -m "$3")
rm -rf "$out" && mkdir -p "$out"
# shellcheck source=../../scripts/mlx.sh
source "$top/scripts/mlx.sh"
ml=$("$top/scripts/meshlab_private.sh" "$out/meshlab") || exit 1
assimp=/usr/share/assimp/models
files=("$data"/{cross,degtri_sliding,fold,hedra_open,cube-ouvert,blobby_3cc,elephant-with-holes,P,tetrahedron,mushroom}.off
  "$assimp"/OBJ/{box.obj,spider.obj,point_cloud.obj,concave_polygon.obj} "$assimp"/PLY/{Wuson.ply,points.ply}
  "$assimp"/STL/{Spider_binary.stl,sphereWithHole.stl} "$assimp"/OFF/{Wuson.off,invalid.off}
  "$assimp"/3DS/fels.3ds "$assimp"/invalid/{empty.obj,empty.ply,malformed.obj,OutOfMemory.off})
passed=0 failed=0 meshlab_crashes=0
ok() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }
server() { # LOG ARGS...: exit code of the private meshlabserver
  local log=$1; shift
  (cd "$out" && LD_LIBRARY_PATH=/usr/lib/x86_64-linux-gnu/meshlab timeout 300 \
    "$top/scripts/lib/on_display.sh" "$ml/meshlabserver" "$@" >"$log" 2>&1)
}
ply_vertices() {
  awk '/^element vertex/ { nv = $3 } /^end_header/ { body = 1; next }
       body && n < nv { printf "%.6g %.6g %.6g\n", $1, $2, $3; n++ }' "$1" | sort -u
}
for f in "${files[@]}"; do
  [ -f "$f" ] || { fail "$f missing (scripts/setup.sh installs libcgal-demo and assimp-testmodels)"; continue; }
  name=$(basename "$f"); name=${name//./_}
  # What MeshLab itself loads (its readers, not ours): the reference for the subset check.
  server "$out/$name-in.log" -i "$f" -o "$out/$name-in.ply" -m sa
  loaded=$?
  for ratio in 0.5 0.1 0.01; do
    { mlx_begin; mlx_vertex_removal TargetPerc=$ratio; mlx_end; } >"$out/s.mlx"
    log=$out/$name-$ratio.log
    rm -f "$out/$name-$ratio.ply"
    server "$log" -i "$f" -o "$out/$name-$ratio.ply" -m sa -s "$out/s.mlx"
    code=$?
    if [ $code -ge 128 ] && [ $code -ne 255 ]; then
      if grep -q "Starting Script" "$log"; then
        fail "$name $ratio: meshlabserver died (exit $code) in the script"
      else
        meshlab_crashes=$((meshlab_crashes + 1)) # MeshLab's reader, before our filter ran
      fi
      continue
    fi
    if [ $loaded -ne 0 ] || ! [ -s "$out/$name-in.ply" ]; then
      ok # MeshLab could not load it: nothing of ours ran, and nothing crashed
    elif [ $code -eq 0 ] && [ -s "$out/$name-$ratio.ply" ]; then
      # Succeeded: a subset of what MeshLab loaded, and the log line.
      if [ -z "$(comm -13 <(ply_vertices "$out/$name-in.ply") <(ply_vertices "$out/$name-$ratio.ply"))" ] &&
        grep -q "Vertex Removal Decimation: " "$log"; then ok; else fail "$name $ratio: not a subset, or no log line"; fi
    elif [ $code -eq 255 ] && grep -q "Vertex Removal Decimation" "$log" && [ ! -e "$out/$name-$ratio.ply" ]; then
      ok # refused with our message, nothing written
    else
      fail "$name $ratio: exit $code without our message: $(grep LOG "$log" | tail -2)"
    fi
  done
done
echo "$passed passed, $failed failed ($((${#files[@]} * 3)) runs on ${#files[@]} files; $meshlab_crashes runs where MeshLab's own reader crashed first)"
[ "$failed" -eq 0 ]
