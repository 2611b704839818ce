#!/usr/bin/env bash
# Runs a command on a private Xvfb display and exits with the command's own status.
#   scripts/lib/on_display.sh [-s 'XVFB ARGS'] COMMAND [ARG...]
# It stands in for `xvfb-run -a`, which has two faults for tests that read exit codes: its
# clean-up can fail and replace the command's status with 5 (a CI run failed that way), and two
# concurrent `-a` runs can race for one display number. Xvfb's -displayfd picks a free display
# atomically and says which; a fresh cookie keeps other users off it.
set -u
xvfb_args=(-screen 0 1280x1024x24)
if [ "${1:-}" = -s ]; then
  read -r -a xvfb_args <<<"$2"
  shift 2
fi
[ $# -gt 0 ] || { echo "usage: on_display.sh [-s 'XVFB ARGS'] COMMAND [ARG...]" >&2; exit 2; }
dir=$(mktemp -d -t vrs-display.XXXXXX) || exit 1
xvfb=""
stop() {
  [ -z "$xvfb" ] || { kill "$xvfb" 2>/dev/null; wait "$xvfb" 2>/dev/null; }
  rm -rf "$dir"
}
trap stop EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

cookie=$(mcookie)
# The server loads every cookie in its file whatever display the entry names; the client's
# file needs the real display number, known only once the server is up.
touch "$dir/server" "$dir/client"
xauth -q -f "$dir/server" add :0 . "$cookie" || exit 1
Xvfb -displayfd 3 -auth "$dir/server" -nolisten tcp "${xvfb_args[@]}" 3>"$dir/number" 2>"$dir/xvfb.log" &
xvfb=$!
for _ in $(seq 300); do
  [ "$(wc -l <"$dir/number")" -ge 1 ] && break
  kill -0 "$xvfb" 2>/dev/null || break
  sleep 0.05
done
number=$(head -1 "$dir/number")
[ -n "$number" ] || { echo "on_display.sh: Xvfb did not start: $(tail -3 "$dir/xvfb.log")" >&2; exit 1; }
xauth -q -f "$dir/client" add ":$number" . "$cookie" || exit 1

DISPLAY=:$number XAUTHORITY=$dir/client "$@"
