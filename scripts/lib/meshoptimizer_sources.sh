#!/usr/bin/env bash
# Fetches and unpacks meshoptimizer's sources from Debian's newer release (the encoder of
# EXT_meshopt_compression for the .glb writer, built into the project as a static library:
# gltf/CMakeLists.txt), pinned by version and sha256, through scripts/lib/debian_source.sh.
#   scripts/lib/meshoptimizer_sources.sh DEST     (DEST gets the unpacked tree)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
version='0.22+dfsg-1' orig='meshoptimizer_0.22+dfsg.orig.tar.xz'
sha=eafe61c2e8840874cb9204f19fc9553d93221f722182ce79c0a1f8d960292470
dest=${1:?usage: meshoptimizer_sources.sh DEST}
[ -f "$dest/.sha256" ] && [ "$(cat "$dest/.sha256")" = "$sha" ] && exit 0
tarball=$("$here/debian_source.sh" meshoptimizer "$version" "$orig" "$sha")
rm -rf "$dest" && mkdir -p "$dest"
tar -xJf "$tarball" -C "$dest" --strip-components=1
echo "$sha" >"$dest/.sha256"
