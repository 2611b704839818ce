#!/usr/bin/env bash
# GUI smoke test: the real MeshLab GUI under Xvfb (software GL) loads the plugin, the filter is
# opened from Filters > Remeshing, Simplification and Reconstruction, applied through its
# dialog, and screenshots are saved with the test output.
#   test_gui.sh REPO_ROOT MESH OUT_DIR [--installed]
# --installed: the system's MeshLab with the plugin the Debian package installed (tests/packaging),
# instead of a private copy holding the build's.
# The clicks are at fixed places: a 1600x1000 screen, MeshLab 2020.09's default window (a fresh
# HOME, so no saved layout), the menu entries in MeshLab's alphabetical order.
set -u

inner() {
  set -u
  HOME="$out/home" LD_LIBRARY_PATH=/usr/lib/x86_64-linux-gnu/meshlab "$ml/meshlab" "$mesh" \
    >"$out/meshlab.log" 2>&1 &
  local pid=$! i
  for i in $(seq 60); do # wait for the window and the mesh
    grep -q "All files opened" "$out/meshlab.log" 2>/dev/null && xdotool search --name MeshLab >/dev/null && break
    sleep 0.5
  done
  sleep 2
  shot() { import -window root "$out/$1.png"; }
  xdotool mousemove 121 10 click 1; sleep 1                 # Filters
  xdotool mousemove 274 161; sleep 0.5; xdotool mousemove 320 161; sleep 1 # Remeshing, ...
  shot 1-remeshing-menu
  xdotool mousemove 560 161 mousemove 678 637; sleep 0.5; shot 2-filter-entry
  xdotool click 1; sleep 2                                  # Simplification: Vertex Removal ...
  shot 3-dialog
  xdotool mousemove 401 711 click 1; sleep 3                # Apply
  xdotool mousemove 138 711 click 1; sleep 2                # Close the dialog
  shot 4-result
  kill "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
  return 0
}
if [ "${1:-}" = --inner ]; then # the part that runs inside Xvfb
  out=$2 ml=$3 mesh=$4
  inner
  exit 0
fi

top=$(realpath "$1") mesh=$(realpath "$2") out=$(realpath -m "$3")
rm -rf "$out" && mkdir -p "$out/home"
if [ "${4:-}" = --installed ]; then
  ml=/usr/bin plugins=/usr/lib/x86_64-linux-gnu/meshlab/plugins
else
  ml=$("$top/scripts/meshlab_private.sh" "$out/meshlab") || exit 1
  plugins=$ml/plugins
fi
timeout 180 "$top/scripts/lib/on_display.sh" -s '-screen 0 1600x1000x24' bash "$0" --inner "$out" "$ml" "$mesh"

passed=0 failed=0
check() { if eval "$1"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $2"; fi; }
check 'grep -q "Current Plugins Dir is: $plugins" "$out/meshlab.log"' "MeshLab did not use the plugins folder $plugins"
check 'grep -q "Applied filter Simplification: Vertex Removal Decimation" "$out/meshlab.log"' \
  "the filter was not applied from the Remeshing menu (see $out/*.png)"
check 'grep -q "Vertex Removal Decimation: 12946 -> 6472 faces" "$out/meshlab.log"' "the default target (half the faces) was not met"
check '[ "$(grep -c "Applied filter" "$out/meshlab.log")" -eq 1 ]' "some other filter was applied too"
for s in 1-remeshing-menu 3-dialog 4-result; do
  check '[ -s "$out/$s.png" ]' "no screenshot $s.png"
done
echo "screenshots: $out/4-result.png (and 1-3)"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
