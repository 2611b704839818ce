#!/usr/bin/env bash
# Makes build/meshlab/: copies of the system's meshlab and meshlabserver with a plugins/ folder
# of their own (the system plugins linked, ours copied), so the plugin runs without touching
# the system. MeshLab looks for plugins/ next to its own executable (/proc/self/exe), hence
# copies, not links. Prints the folder.
#   scripts/meshlab_private.sh [DIR]     (default build/meshlab)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
dir=$(realpath -m "${1:-$top/build/meshlab}")
ours="$top/build/plugins/libfilter_vertex_removal.so"
system=/usr/lib/x86_64-linux-gnu/meshlab/plugins
[ -f "$ours" ] || { echo "meshlab_private: $ours not built (scripts/build.sh -DVRS_BUILD_PLUGIN=ON)" >&2; exit 1; }
rm -rf "$dir" && mkdir -p "$dir/plugins"
cp /usr/bin/meshlabserver /usr/bin/meshlab "$dir/"
for p in "$system"/*.so; do
  # An installed copy of ours would load twice under the same filter name.
  [ "$(basename "$p")" = libfilter_vertex_removal.so ] || ln -s "$p" "$dir/plugins/"
done
cp "$ours" "$dir/plugins/"
echo "$dir"
