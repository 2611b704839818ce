#!/usr/bin/env bash
# The real MeshLab 2022.02 or 2025.07 GUI (Debian trixie's or sid's package, in a root made by
# scripts/lib/meshlab_root.sh) under Xvfb: our Debian package for that MeshLab is packed from
# the build (cpack) and installed into the root with `apt-get install ./file.deb`, the filter is
# found in Filters > Remeshing, Simplification and Reconstruction, applied from its dialog, then
# applied with a bad parameter: MeshLab's failure dialog must show our message and the layer
# stay as it was. Then a polygon mesh (quads, pentagons, hexagons) is simplified and exported
# with MeshLab's default options (polygons kept: what threw std::bad_alloc once): the file is
# written, its polygons split into the triangles the log reports. Then `apt-get remove` takes
# the plugin away and MeshLab still opens the mesh.
# Screenshots go with the output.
#   test_gui_newer.sh 2022.02|2025.07 ROOT BUILD_DIR MESH OUT_DIR
# The clicks are at fixed places (a 1600x1000 screen, a fresh HOME, MeshLab's default layout);
# they differ between the two versions, hence the table below.
set -u
version=$1 root=$(realpath "$2") build=$(realpath "$3") mesh=$(realpath "$4") out=$(realpath -m "$5")
here=$(cd "$(dirname "$0")" && pwd)
case "$version" in #      filter entry      Apply        Levels of detail field
  2022.02) component=meshlab2022 entry="637 677" apply="685 713" levels="653 546" ;;
  2025.07) component=meshlab2025 entry="637 620" apply="685 773" levels="653 517" ;;
  *) echo "usage: test_gui_newer.sh 2022.02|2025.07 ROOT BUILD_DIR MESH OUT_DIR"; exit 2 ;;
esac
plugin="$root/usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_vertex_removal.so"

inner() {
  set -u
  HOME=/tmp/vrs-home "$here/../../scripts/lib/in_root.sh" "$root" meshlab "/tmp/vrs-gui/$(basename "$mesh")" \
    >"$out/meshlab.log" 2>&1 &
  local pid=$! i
  for i in $(seq 60); do # wait for the window and the mesh
    grep -q "All files opened" "$out/meshlab.log" 2>/dev/null && xdotool search --name MeshLab >/dev/null && break
    sleep 0.5
  done
  sleep 2
  shot() { import -window root "$out/$1.png"; }
  xdotool mousemove 116 9 click 1; sleep 1                                 # Filters
  xdotool mousemove 260 148; sleep 0.5; xdotool mousemove 300 148; sleep 1 # Remeshing, ...
  xdotool mousemove 600 148; sleep 0.3; xdotool mousemove $entry; sleep 0.5
  shot 1-remeshing-menu
  xdotool click 1; sleep 2                                                 # our filter
  shot 2-dialog
  xdotool mousemove $apply click 1; sleep 3                                # Apply
  shot 3-applied
  xdotool mousemove $levels click --repeat 3 1; sleep 0.3
  xdotool key ctrl+a type 99; sleep 0.3                                    # Levels of detail: 99
  xdotool mousemove $apply click 1; sleep 2
  shot 4-failure-dialog
  xdotool key Return; sleep 0.5                                            # OK
  xdotool mousemove $levels click --repeat 3 1; sleep 0.3
  xdotool key ctrl+a type 1; sleep 0.3
  xdotool mousemove $apply click 1; sleep 2                                # Apply again
  shot 5-after-failure
  pkill -f "meshlab /tmp/vrs-gui/" 2>/dev/null; wait "$pid" 2>/dev/null
  return 0
}

polygons() { # the filter on a polygon OFF, then File > Export Mesh (ctrl+e) with the defaults
  HOME=/tmp/vrs-home "$here/../../scripts/lib/in_root.sh" "$root" meshlab /tmp/vrs-gui/sheet.off \
    >"$out/meshlab-polygons.log" 2>&1 &
  local pid=$! i
  for i in $(seq 60); do
    grep -q "All files opened" "$out/meshlab-polygons.log" 2>/dev/null && xdotool search --name MeshLab >/dev/null && break
    sleep 0.5
  done
  sleep 2
  xdotool mousemove 116 9 click 1; sleep 1
  xdotool mousemove 260 148; sleep 0.5; xdotool mousemove 300 148; sleep 1
  xdotool mousemove 600 148; sleep 0.3; xdotool mousemove $entry; sleep 0.5
  xdotool click 1; sleep 2
  xdotool mousemove $apply click 1; sleep 3                                # Apply: half the faces
  xdotool key ctrl+e; sleep 2                                              # Export Mesh
  import -window root "$out/6-export-options.png"
  xdotool key Return; sleep 2                                              # its options: OK
  pkill -f "meshlab /tmp/vrs-gui/" 2>/dev/null; wait "$pid" 2>/dev/null
  return 0
}

after() { # MeshLab alone, once the package is removed: it starts and opens the mesh
  HOME=/tmp/vrs-home "$here/../../scripts/lib/in_root.sh" "$root" meshlab "/tmp/vrs-gui/$(basename "$mesh")" \
    >"$out/meshlab-after.log" 2>&1 &
  local pid=$! i
  for i in $(seq 60); do
    grep -q "All files opened" "$out/meshlab-after.log" 2>/dev/null && break
    sleep 0.5
  done
  pkill -f "meshlab /tmp/vrs-gui/" 2>/dev/null; wait "$pid" 2>/dev/null
  return 0
}

if [ "${VRS_GUI_INNER:-}" = 1 ]; then inner; exit 0; fi
if [ "${VRS_GUI_AFTER:-}" = 1 ]; then after; exit 0; fi
if [ "${VRS_GUI_POLYGONS:-}" = 1 ]; then polygons; exit 0; fi
rm -rf "$out" && mkdir -p "$out"

# Install as a user would, into the root standing in for that Debian system; removed again at
# the end so that the cached root stays as debootstrap made it.
in_root() { "$here/../../scripts/lib/in_root.sh" "$root" env DEBIAN_FRONTEND=noninteractive "$@"; }
(cd "$build" && cpack -G DEB -D CPACK_COMPONENTS_ALL="$component" -B "$out/pack" >"$out/cpack.log" 2>&1)
deb=$(ls "$out"/pack/meshlab-filter-vertex-removal_*.deb 2>/dev/null) || { echo "FAIL: cpack (see $out/cpack.log)"; exit 1; }
remove() { in_root apt-get remove -y -qq meshlab-filter-vertex-removal >>"$out/install.log" 2>&1; }
trap 'remove; rm -f "$root/tmp/$(basename "$deb")"; rm -rf "$root/tmp/vrs-gui" "$root/tmp/vrs-home"' EXIT
cp "$deb" "$root/tmp/"
in_root apt-get install -y -qq "/tmp/$(basename "$deb")" >"$out/install.log" 2>&1 || {
  echo "FAIL: apt-get install ./$(basename "$deb") (see $out/install.log)"; exit 1; }
mkdir -p "$root/tmp/vrs-gui" "$root/tmp/vrs-home" && cp "$mesh" "$root/tmp/vrs-gui/"
VRS_GUI_INNER=1 timeout 180 "$here/../../scripts/lib/on_display.sh" -s '-screen 0 1600x1000x24' bash "$0" "$@"
faces=$(awk 'NF && $1 !~ /^#/ { n++; if (n == 2) { print $2; exit } }' "$mesh")
half=$(( (faces + 1) / 2 ))

passed=0 failed=0
check() { if eval "$1"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $2"; fi; }
log="$out/meshlab.log"
check 'in_root dpkg -L meshlab-filter-vertex-removal | grep -qx "${plugin#"$root"}" && [ -f "$plugin" ]' \
  "the package did not install the plugin into MeshLab's plugins folder"
check '! grep -q "Unable to load\|does not seem to be\|different version\|different floating" "$log"' "MeshLab refused the plugin"
check 'grep -Eq "Applied filter:? Simplification: Vertex Removal Decimation" "$log"' \
  "the filter was not applied from the Remeshing menu (see $out/*.png)"
check 'grep -Eq "Vertex Removal Decimation: $faces -> [0-9]+ faces" "$log"' "no log line for the first run"
check '[ "$(grep -Eo "$faces -> [0-9]+ faces" "$log" | head -1 | grep -Eo "[0-9]+ faces" | grep -Eo "[0-9]+")" -le "$half" ]' \
  "the default target (half the faces) was not met"
check 'grep -q "Vertex Removal Decimation failed: Levels of detail must be in \[1, 16\], got 99" "$log"' \
  "no failure reported for Levels of detail 99"
first_out=$(grep -Eo "Decimation: $faces -> [0-9]+" "$log" | head -1 | grep -Eo "[0-9]+$")
check '[ -n "$first_out" ] && grep -Eq "Vertex Removal Decimation: $first_out -> [0-9]+ faces" "$log"' \
  "after the failure the layer was not the one the first run left"
check '[ "$(grep -Ec "Applied filter:? " "$log")" -eq 2 ]' "not exactly two successful applications"
for s in 1-remeshing-menu 2-dialog 3-applied 4-failure-dialog 5-after-failure; do
  check '[ -s "$out/$s.png" ]' "no screenshot $s.png"
done

# Polygons: exported after the filter with the default options (polygonal).
python3 "$here/../support/polygon_sheet.py" "$root/tmp/vrs-gui/sheet.off"
VRS_GUI_POLYGONS=1 timeout 180 "$here/../../scripts/lib/on_display.sh" -s '-screen 0 1600x1000x24' bash "$0" "$@"
plog="$out/meshlab-polygons.log"
cp "$root/tmp/vrs-gui/sheet.off" "$out/sheet-exported.off"
kept=$(grep -Eo "Vertex Removal Decimation: 3200 -> [0-9]+ faces" "$plog" | head -1 | grep -Eo "[0-9]+ faces" | grep -Eo "[0-9]+")
check '[ -n "$kept" ] && [ "$kept" -le 1600 ]' "the polygon sheet was not simplified (see $plog)"
check 'grep -q "Saved Mesh /tmp/vrs-gui/sheet.off" "$plog"' "the export after the filter did not save (see $plog)"
split=$(awk 'NF && $1 !~ /^#/ { k++; if (k == 2) nf = $2; else if (k > 2 && NF > 3 && $1 == NF - 1 && n < nf) { t += $1 - 2; p += ($1 > 3); n++ } } END { print t + 0, p + 0 }' "$out/sheet-exported.off")
check '[ "${split% *}" = "$kept" ] && [ "${split#* }" -gt 0 ]' \
  "the exported polygons (triangles, polygons: $split) are not the $kept faces the filter left"

# Removed, MeshLab still starts and opens the mesh (and no longer lists the filter's plugin).
remove
check '[ ! -e "$plugin" ]' "the plugin is still there after apt-get remove"
VRS_GUI_AFTER=1 timeout 120 "$here/../../scripts/lib/on_display.sh" -s '-screen 0 1600x1000x24' bash "$0" "$@"
check 'grep -q "All files opened" "$out/meshlab-after.log"' \
  "MeshLab does not open the mesh after the package's removal (see $out/meshlab-after.log)"
echo "MeshLab $version ($(cat "$root/.meshlab-version")): screenshots in $out"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
