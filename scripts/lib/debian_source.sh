#!/usr/bin/env bash
# Fetches one orig tarball of a newer Debian release's source package (trixie or sid) into
# $VRS_CACHE/src, pinned by version and sha256, and prints its path. apt runs with a
# configuration of its own (its own sources list, lists and cache under $VRS_CACHE/apt): trixie
# and sid are never added to this machine's sources. The mirror is the one this machine's apt
# already uses. Only the orig tarball is wanted (apt exits non-zero on the .dsc it does not
# find: the sha256 check is what decides).
#   scripts/lib/debian_source.sh PACKAGE VERSION ORIG_TARBALL SHA256
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
cache=${VRS_CACHE:-/var/cache/vrsimplify}
package=$1 version=$2 orig=$3 sha=$4
tarball=$cache/src/$orig
if ! echo "$sha  $tarball" | sha256sum -c --status 2>/dev/null; then
  apt_dir=$cache/apt
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
  listed=$(apt-cache "${opts[@]}" showsrc "$package" | awk -v v="$version" -v f="$orig" '
    /^Package:/ {ver = ""} /^Version:/ {ver = $2}
    /^[^ ]/ {sums = ($1 == "Checksums-Sha256:")} sums && ver == v && $3 == f {print $1}' | head -n 1)
  [ "$listed" = "$sha" ] || { echo "debian_source: the archive lists $orig with sha256 '$listed', pinned $sha" >&2; exit 1; }
  (cd "$cache/src" && apt-get "${opts[@]}" source --download-only "$package=$version" >/dev/null 2>&1 || true)
  echo "$sha  $tarball" | sha256sum -c --status || { echo "debian_source: $orig missing or not the pinned one" >&2; exit 1; }
fi
echo "$tarball"
