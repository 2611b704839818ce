#!/usr/bin/env bash
# Configures and builds into build/ (Release): core, CLI, benchmark, tests, and the MeshLab
# plugin for every host set up here: MeshLab 2020.09 always; pymeshlab when setup made its
# virtual environment; MeshLab 2022.02 and 2025.07 when `scripts/setup.sh --roots` made the
# trixie and sid roots that hold them (their libmeshlab-common is what the plugin links to).
# Extra arguments go to cmake.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cache=${VRS_CACHE:-/var/cache/vrsimplify}
hosts=()
for pymeshlab in "$cache"/venv/lib/python3*/site-packages/pymeshlab; do
  [ -f "$pymeshlab/lib/libmeshlab-common.so" ] &&
    hosts+=(-DVRS_MESHLAB2025_SOURCE="$top/third_party/meshlab-2025.07" -DVRS_PYMESHLAB_DIR="$pymeshlab")
done
for host in 2022:2022.02:trixie 2025:2025.07:sid; do
  IFS=: read -r api version suite <<<"$host"
  lib="$cache/roots/$suite/usr/lib/x86_64-linux-gnu/meshlab"
  [ -f "$cache/roots/$suite/.ready" ] && [ -f "$lib/libmeshlab-common.so" ] &&
    hosts+=(-DVRS_MESHLAB${api}_SOURCE="$top/third_party/meshlab-$version" -DVRS_MESHLAB${api}_LIBDIR="$lib")
done
cmake -S "$top" -B "$top/build" -DCMAKE_BUILD_TYPE=Release -DVRS_BUILD_PLUGIN=ON -DVRS_BUILD_BENCH=ON \
  "${hosts[@]}" "$@" >/dev/null
cmake --build "$top/build" -j "$(nproc)"
