#!/usr/bin/env bash
# A tiled run stopped part way (Ctrl-C, kill, a closed terminal, its driver killed) leaves no
# work directory, no output or temporary file and no process behind, and ends as the signal
# says; a run left alone afterwards still succeeds.
#   test_interrupt.sh VRSIMPLIFY VRS_BENCH OUT_DIR
set -u
set -m # background runs get their own process group, SIGINT not ignored: Ctrl-C as a terminal sends it
bin=$1 bench=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
passed=0 failed=0
ok() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }

"$bench" --streamed-terrain 1025 "$out/terrain.ply" >/dev/null || { echo "FAIL: no terrain"; exit 1; }
mkdir "$out/run"

# how: ctrl-c | term | hup | kill-driver; expected exit status
stop_run() {
  local how=$1 want=$2
  # As from a terminal even if this script was started with SIGINT ignored (a background job).
  env --default-signal=INT,TERM,HUP "$bin" "$out/terrain.ply" "$out/run/o.ply" --ratio 0.01 --memory 16M --workers 2 2>"$out/err" &
  local pid=$!
  # Stopped while tile workers run (the guard, the driver and at least one worker).
  local running=0
  for _ in $(seq 600); do
    running=$(pgrep -g "$pid" | wc -l)
    [ "$running" -ge 3 ] && break
    sleep 0.05
  done
  case $how in
  ctrl-c) kill -INT -- "-$pid" ;;
  term) kill -TERM "$pid" ;;
  hup) kill -HUP "$pid" ;;
  kill-driver) kill -KILL "$(pgrep -P "$pid" | head -n 1)" ;;
  esac
  wait "$pid"
  local rc=$?
  local left; left=$(ls -A "$out/run")
  local procs; procs=$(pgrep -g "$pid")
  [ "$running" -ge 3 ] || fail "$how: the run was not going (${running} processes)"
  [ "$rc" -eq "$want" ] && [ -z "$left" ] && [ -z "$procs" ] && grep -q "stopped (.*); removed" "$out/err" && ok ||
    fail "$how: exit $rc (want $want), left [$left], processes [$procs]: $(cat "$out/err")"
}
stop_run ctrl-c 130
stop_run term 143
stop_run hup 129
stop_run kill-driver 137

# Left alone, the same run succeeds and cleans up after itself.
"$bin" "$out/terrain.ply" "$out/run/o.ply" --ratio 0.01 --memory 16M --workers 2 --quiet >/dev/null 2>"$out/err" &&
  [ "$(ls -A "$out/run")" = o.ply ] && ok || fail "an uninterrupted run: $(cat "$out/err")"

echo "interrupt: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
