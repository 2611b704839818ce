#!/usr/bin/env bash
# Builds the Debian packages of the filter into dist/, one per MeshLab the build has: bookworm
# (MeshLab 2020.09, always), trixie (2022.02) and sid (2025.07) when `scripts/setup.sh --roots`
# made their roots. Each depends on its exact MeshLab (plugin/debian_packages.cmake).
#   scripts/build_debs.sh      -> dist/meshlab-filter-vertex-removal_<version>~<suite>_amd64.deb
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$top/build"
"$top/scripts/build.sh" >"$top/build/build_debs.log" 2>&1 || { tail -n 40 "$top/build/build_debs.log" >&2; exit 1; }
components=$(sed -n 's/^VRS_DEB_COMPONENTS:INTERNAL=//p' "$top/build/CMakeCache.txt" | tr ';' ' ')
[ -n "$components" ] || { echo "build_debs: no MeshLab to package for" >&2; exit 1; }
mkdir -p "$top/dist"
rm -f "$top"/dist/meshlab-filter-vertex-removal_*.deb
for c in $components; do
  (cd "$top/build" && cpack -G DEB -D CPACK_COMPONENTS_ALL="$c" -B "$top/build/debs" >/dev/null)
done
mv "$top"/build/debs/meshlab-filter-vertex-removal_*.deb "$top/dist/"
ls -1 "$top"/dist/meshlab-filter-vertex-removal_*.deb
