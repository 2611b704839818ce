#!/usr/bin/env bash
# The Debian package for this machine's MeshLab 2020.09 as a user installs it: packed from the
# build (cpack), `apt-get install ./file.deb`, then the system's own meshlabserver runs our
# .mlx script and the system's MeshLab GUI shows and applies the filter (test_gui.sh
# --installed); `apt-get remove` takes the plugin away and leaves MeshLab working (QECD
# through meshlabserver). Runs alone (ctest RUN_SERIAL): it changes the system's MeshLab.
#   test_deb_bookworm.sh REPO_ROOT BUILD_DIR OUT_DIR
set -u
top=$(realpath "$1") build=$(realpath "$2") out=$(realpath -m "$3")
plugin=/usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_vertex_removal.so
rm -rf "$out" && mkdir -p "$out"
passed=0 failed=0
check() { if eval "$1"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $2"; fi; }
faces() { awk 'NR == 2 { print $2; exit }' "$1"; } # OFF: the counts line

(cd "$build" && cpack -G DEB -D CPACK_COMPONENTS_ALL=meshlab2020 -B "$out/pack" >"$out/cpack.log" 2>&1)
deb=$(ls "$out"/pack/meshlab-filter-vertex-removal_*~bookworm_amd64.deb 2>/dev/null)
check '[ -f "$deb" ]' "cpack made no package (see $out/cpack.log)"
[ -f "$deb" ] || { echo "$passed passed, $failed failed"; exit 1; }
remove() { DEBIAN_FRONTEND=noninteractive apt-get remove -y -qq meshlab-filter-vertex-removal >>"$out/apt.log" 2>&1; }
trap remove EXIT
check '[ ! -e "$plugin" ]' "a plugin is already in MeshLab's folder before the install"

DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "$deb" >"$out/apt.log" 2>&1
check 'dpkg-query -W -f="\${Status}" meshlab-filter-vertex-removal | grep -q "install ok installed"' \
  "apt-get install $deb failed (see $out/apt.log)"
check 'dpkg -L meshlab-filter-vertex-removal | grep -qx "$plugin"' "the package does not hold $plugin"

# The installed files only: the system's meshlabserver, our shipped script.
"$top/scripts/lib/on_display.sh" meshlabserver -i "$top/meshes/fandisk.off" -o "$out/fandisk-10.off" \
  -s "$top/plugin/scripts/vertex_removal_10pct.mlx" >"$out/meshlabserver.log" 2>&1
check '[ -s "$out/fandisk-10.off" ] && [ "$(faces "$out/fandisk-10.off")" -le 1295 ]' \
  "meshlabserver with the installed plugin did not reach 10 % (see $out/meshlabserver.log)"
bash "$top/tests/plugin/test_gui.sh" "$top" "$top/meshes/fandisk.off" "$out/gui" --installed >"$out/gui.log" 2>&1
check '[ $? -eq 0 ]' "the GUI test with the installed plugin failed: $(grep FAIL "$out/gui.log" | head -3)"

remove
check '! dpkg-query -W -f="\${Status}" meshlab-filter-vertex-removal 2>/dev/null | grep -q "install ok installed"' "apt-get remove failed"
check '[ ! -e "$plugin" ]' "the plugin is still in MeshLab's folder after removal"
# shellcheck source=../../scripts/mlx.sh
source "$top/scripts/mlx.sh"
{ mlx_begin; mlx_qecd TargetFaceNum=1000; mlx_end; } >"$out/qecd.mlx"
"$top/scripts/lib/on_display.sh" meshlabserver -i "$top/meshes/fandisk.off" -o "$out/fandisk-qecd.off" -s "$out/qecd.mlx" \
  >"$out/meshlabserver-after.log" 2>&1
check '[ -s "$out/fandisk-qecd.off" ] && [ "$(faces "$out/fandisk-qecd.off")" -le 1000 ]' \
  "MeshLab no longer works after the removal (see $out/meshlabserver-after.log)"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
