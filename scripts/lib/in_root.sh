#!/usr/bin/env bash
# Runs a command inside a Debian root made by meshlab_root.sh, with /proc, /dev and this
# machine's X socket folder (so a program inside can use an Xvfb display started outside) bound
# in a private mount namespace: the mounts vanish with the command, even if it is killed.
#   scripts/lib/in_root.sh ROOT COMMAND [ARG...]
# DISPLAY and HOME are passed in, and the X authority file (as on_display.sh makes one) copied in.
set -euo pipefail
root=$(realpath "${1:?usage: in_root.sh ROOT COMMAND...}")
shift
mkdir -p "$root/tmp/.X11-unix"
xauth=""
if [ -n "${XAUTHORITY:-}" ] && [ -r "$XAUTHORITY" ]; then
  xauth="/tmp/.vrs-xauth.$$"
  export XAUTH_IN_ROOT=$xauth
  cp "$XAUTHORITY" "$root$xauth"
fi
unshare --mount --propagation private bash -c '
  set -e
  root=$1; shift
  mount -t proc proc "$root/proc"
  mount --bind /dev "$root/dev"
  mount --bind /tmp/.X11-unix "$root/tmp/.X11-unix"
  exec chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin DISPLAY="${DISPLAY:-}" \
    HOME="${HOME:-/root}" XAUTHORITY="$XAUTH_IN_ROOT" LANG=C.UTF-8 QT_X11_NO_MITSHM=1 "$@"' in_root "$root" "$@" && status=0 || status=$?
[ -z "$xauth" ] || rm -f "$root$xauth"
exit "$status"
