#!/usr/bin/env bash
# scripts/lib/on_display.sh, which every MeshLab test runs under: the command's own exit status
# comes back unchanged, concurrent runs get displays of their own, the display refuses clients
# without its cookie, and nothing is left behind.
#   test_on_display.sh REPO_ROOT
set -u
run=$1/scripts/lib/on_display.sh
passed=0 failed=0
check() { if eval "$1"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $2"; fi; }
# A private TMPDIR, so that what is left behind is ours alone to count.
TMPDIR=$(mktemp -d) && export TMPDIR
out=$(mktemp -d -p /tmp vrs-on-display-test.XXXXXX)
trap 'rm -rf "$TMPDIR" "$out"' EXIT

"$run" sh -c 'xdotool getdisplaygeometry >/dev/null && exit 7'
check '[ $? -eq 7 ]' "the command's exit status 7 did not come back"
"$run" sh -c 'exit 255'
check '[ $? -eq 255 ]' "the command's exit status 255 did not come back"
size=$("$run" -s '-screen 0 640x480x24' xdotool getdisplaygeometry | tr " " x)
check '[ "$size" = 640x480 ]' "-s did not reach Xvfb (screen $size)"
check '"$run" sh -c "XAUTHORITY=/dev/null xdotool getdisplaygeometry" >/dev/null 2>&1; [ $? -ne 0 ]' "a client without the cookie was let in"
hold='echo "$DISPLAY"; sleep 2; xdotool getdisplaygeometry >/dev/null'
"$run" sh -c "$hold" >"$out/on_display.a" & a=$!
"$run" sh -c "$hold" >"$out/on_display.b" & b=$!
wait $a; sa=$?; wait $b; sb=$?
da=$(cat "$out/on_display.a") db=$(cat "$out/on_display.b")
rm -f "$out/on_display".[ab]
check '[ $sa -eq 0 ] && [ $sb -eq 0 ] && [ -n "$da" ] && [ "$da" != "$db" ]' \
  "two concurrent runs: displays '$da' and '$db', status $sa and $sb"
check '[ -z "$(ls -A "$TMPDIR")" ]' "left in TMPDIR: $(ls -A "$TMPDIR")"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
