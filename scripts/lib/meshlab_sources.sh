#!/usr/bin/env bash
# Fetches and unpacks the MeshLab source tarball of one of the newer Debian releases (headers and
# vcglib for building the plugin against MeshLab 2022.02 or 2025.07), pinned by version and
# sha256, through scripts/lib/debian_source.sh.
#   scripts/lib/meshlab_sources.sh 2022.02|2025.07 DEST     (DEST gets the unpacked tree)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
cache=${VRS_CACHE:-/var/cache/vrsimplify}
case "${1:-}" in
  2022.02) version='2022.02+dfsg1-1' orig='meshlab_2022.02+dfsg1.orig.tar.xz'
           sha=11da26ec46c3fbbbc806d410a3221542ec21ec13fdcc55d624304600029435fd ;;
  2025.07) version='2025.07~dfsg-4' orig='meshlab_2025.07~dfsg.orig.tar.xz'
           sha=d22c98d362f2a284e481af8dbfc272b2222f5b9c67b3cf8bec57d1c3161886f4 ;;
  *) echo "usage: meshlab_sources.sh 2022.02|2025.07 DEST" >&2; exit 2 ;;
esac
dest=${2:?usage: meshlab_sources.sh 2022.02|2025.07 DEST}
[ -f "$dest/.sha256" ] && [ "$(cat "$dest/.sha256")" = "$sha" ] && exit 0

tarball=$("$here/debian_source.sh" meshlab "$version" "$orig" "$sha")
rm -rf "$dest" && mkdir -p "$dest"
tar -xJf "$tarball" -C "$dest" --strip-components=1
echo "$sha" >"$dest/.sha256"
