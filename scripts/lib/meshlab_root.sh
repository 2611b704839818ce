#!/usr/bin/env bash
# Makes (once; cached under $VRS_CACHE/roots) a minimal Debian root holding the real MeshLab of a
# newer release, to run its GUI here under Xvfb: trixie has MeshLab 2022.02, sid 2025.07. The
# root is disposable and never touches this machine's own packages. Prints the root's path.
#   scripts/lib/meshlab_root.sh trixie|sid
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
cache=${VRS_CACHE:-/var/cache/vrsimplify}
case "${1:-}" in
  trixie) want=2022.02 ;;
  sid) want=2025.07 ;;
  *) echo "usage: meshlab_root.sh trixie|sid" >&2; exit 2 ;;
esac
suite=$1
root="$cache/roots/$suite"
if [ ! -f "$root/.ready" ]; then
  [ "$(id -u)" -eq 0 ] || { echo "meshlab_root: debootstrap and chroot need root" >&2; exit 1; }
  command -v debootstrap >/dev/null || { echo "meshlab_root: debootstrap missing (scripts/setup.sh installs it)" >&2; exit 1; }
  tmp="$root.tmp"
  rm -rf "$tmp" && mkdir -p "$(dirname "$root")"
  echo "meshlab_root: debootstrap $suite (a few minutes, once)" >&2
  debootstrap --variant=minbase --keyring=/usr/share/keyrings/debian-archive-keyring.gpg \
    "$suite" "$tmp" "$("$here/debian_mirror.sh")" >"$cache/roots/$suite.log" 2>&1 ||
    { tail -n 20 "$cache/roots/$suite.log" >&2; exit 1; }
  # Inside the root only: an archive snapshot's sid Release may be past its Valid-Until.
  echo 'Acquire::Check-Valid-Until "false";' >"$tmp/etc/apt/apt.conf.d/99vrs-snapshot"
  # With its Recommends, else six of MeshLab's own plugins fail to load.
  chroot "$tmp" env DEBIAN_FRONTEND=noninteractive sh -c \
    'apt-get update -qq && apt-get install -y -qq meshlab && apt-get clean' \
    >>"$cache/roots/$suite.log" 2>&1 || { tail -n 20 "$cache/roots/$suite.log" >&2; exit 1; }
  got=$(chroot "$tmp" dpkg-query -W -f='${Version}' meshlab)
  case "$got" in
    "$want"*) ;;
    *) echo "meshlab_root: $suite now serves meshlab $got, the plugin is built for $want" >&2; exit 1 ;;
  esac
  echo "$got" >"$tmp/.meshlab-version"
  touch "$tmp/.ready"
  rm -rf "$root" && mv "$tmp" "$root"
fi
echo "$root"
