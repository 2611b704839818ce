#!/usr/bin/env bash
# Configures and builds into build/ (Release): core, CLI, MeshLab plugin, benchmark, tests. Extra
# arguments go to cmake.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cmake -S "$top" -B "$top/build" -DCMAKE_BUILD_TYPE=Release -DVRS_BUILD_PLUGIN=ON -DVRS_BUILD_BENCH=ON "$@" >/dev/null
cmake --build "$top/build" -j "$(nproc)"
