#!/usr/bin/env bash
# Fetches and unpacks the MeshLab source tarball of one of the newer Debian releases (headers and
# vcglib for building the plugin against MeshLab 2022.02 or 2025.07), pinned by version and
# sha256. apt runs with a configuration of its own (its own sources list, lists and cache under
# $VRS_CACHE/apt): trixie and sid are never added to this machine's sources. The mirror is the
# one this machine's apt already uses. Only the orig tarball is wanted (apt exits non-zero on
# the .dsc it does not find: the sha256 check is what decides).
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

tarball="$cache/src/$orig"
if ! echo "$sha  $tarball" | sha256sum -c --status 2>/dev/null; then
  apt_dir="$cache/apt"
  mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$cache/src"
  mirror=$("$here/debian_mirror.sh")
  key=/usr/share/keyrings/debian-archive-keyring.gpg
  printf 'deb-src [signed-by=%s] %s trixie main\ndeb-src [signed-by=%s] %s sid main\n' \
    "$key" "$mirror" "$key" "$mirror" >"$apt_dir/sources.list"
  # sid's Release in an archive snapshot may be past its Valid-Until.
  opts=(-o "Dir::Etc::SourceList=$apt_dir/sources.list" -o Dir::Etc::SourceParts=/dev/null
        -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache=$apt_dir/cache"
        -o Acquire::Check-Valid-Until=false)
  apt-get "${opts[@]}" update -qq
  # The Sources stanza of that version: its Checksums-Sha256 line for the orig tarball.
  listed=$(apt-cache "${opts[@]}" showsrc meshlab | awk -v v="$version" -v f="$orig" '
    /^Package:/ {ver = ""} /^Version:/ {ver = $2}
    /^[^ ]/ {sums = ($1 == "Checksums-Sha256:")} sums && ver == v && $3 == f {print $1}' | head -n 1)
  [ "$listed" = "$sha" ] || { echo "meshlab_sources: the archive lists $orig with sha256 '$listed', pinned $sha" >&2; exit 1; }
  (cd "$cache/src" && apt-get "${opts[@]}" source --download-only "meshlab=$version" >/dev/null 2>&1 || true)
  echo "$sha  $tarball" | sha256sum -c --status || { echo "meshlab_sources: $orig missing or not the pinned one" >&2; exit 1; }
fi
rm -rf "$dest" && mkdir -p "$dest"
tar -xJf "$tarball" -C "$dest" --strip-components=1
echo "$sha" >"$dest/.sha256"
