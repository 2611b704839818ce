#!/usr/bin/env bash
# Makes (once; cached under $VRS_CACHE/roots) a minimal Debian root holding the real MeshLab of a
# newer release, to run its GUI here under Xvfb: trixie has MeshLab 2022.02, sid 2025.07 (and
# CPython 3.14 and 3.15 for the wheel's tests). The root is disposable and never touches this
# machine's own packages. Prints the root's path.
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
# The sid root also runs the wheel's tests on CPython 3.15 (scripts/test_wheel.sh): PyPI has no
# numpy for it yet, Debian's is built for 3.14 and 3.15, as are pip and the C extensions Dask's
# distributed needs. Added to a root made before, too.
if [ "$suite" = sid ] && [ ! -f "$root/.python3.15" ]; then
  chroot "$root" env DEBIAN_FRONTEND=noninteractive sh -c \
    'apt-get update -qq && apt-get install -y -qq python3.15 python3-numpy python3-pip \
       python3-yaml python3-msgpack python3-psutil python3-tornado python3-markupsafe && apt-get clean' \
    >>"$cache/roots/$suite.log" 2>&1 || { tail -n 20 "$cache/roots/$suite.log" >&2; exit 1; }
  touch "$root/.python3.15"
fi
echo "$root"
