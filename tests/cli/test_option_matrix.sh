#!/usr/bin/env bash
# One behaviour in core and tiled: every option of `vrsimplify --help`, run in core and tiled
# (--memory 1M on a 76 k-face mesh forces tiles). In core, an option that changes the output
# changes it (against the run without it). Tiled, it is honoured (the output changes as in
# core, or it does not change the output in core either) or refused before any work: exit 2,
# one line naming the option, no output file, no work directory. An option --help lists and this
# table lacks fails the test, so a new option cannot slip past.
#   test_option_matrix.sh VRSIMPLIFY CGAL_DATA OUT_DIR
set -u
bin=$1 data=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
in=$out/bunny.ply
"$bin" "$data/bunny00.off" "$in" --ratio 1 --quiet >/dev/null || { echo "cannot make the input"; exit 1; }
passed=0 failed=0
ok() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $1"; }
# option -> the arguments that exercise it (with --ratio 0.1 unless it sets its own target).
declare -A args=(
  [--ascii]="--ascii" [--auto]="--auto" [--error-bound]="--error-bound" [--faces]="--faces 5000"
  [--feature-angle]="--feature-angle 30" [--fill]="--fill projection" [--intervals]="--intervals 50"
  [--json]="--json" [--keep-boundary]="--keep-boundary" [--mapping]="--mapping linear" [--no-slide]="--no-slide"
  [--max-error]="--max-error 0.5%" [--max-factor]="--max-factor 0.001" [--max-jump]="--max-jump 2"
  [--mode]="--mode planar" [--priority]="--priority factor" [--progress]="--progress"
  [--queue]="--queue heap" [--ratio]="--ratio 0.2" [--reprice]="--reprice eager"
  [--simplify-boundary]="--simplify-boundary" [--split-vertices]="--split-vertices keep"
  [--threads]="--threads 1" [--version]="--version"
  [--vertices]="--vertices 3000" [--memory]="" [--scheduler]="" [--work-dir]="" [--workers]="--workers 1"
  [--lods]="" [--compress]="" [--progressive]=""
)
# Options that are about the run, not the mesh: the same output with or without them.
same_output=" --json --progress --threads --workers --error-bound --ascii "
for opt in $("$bin" --help | grep -oE "^\s+--[a-z-]+" | tr -d ' ' | sort -u); do
  [ -n "${args[$opt]+set}" ] || { fail "$opt is listed by --help but not in this test's table"; continue; }
done
"$bin" "$in" "$out/base-core.ply" --ratio 0.1 --quiet >/dev/null || fail "the in-core base run"
"$bin" "$in" "$out/base-tiled.ply" --ratio 0.1 --memory 1M --quiet >/dev/null || fail "the tiled base run"
for opt in "${!args[@]}"; do
  a=${args[$opt]}
  # The tiled switch itself, no run, or a .glb output (tests/web/test_glb.sh: --lods and
  # --progressive with any other output and with --memory are refused there).
  case $opt in --memory|--scheduler|--work-dir|--version|--lods|--compress|--progressive) continue ;; esac
  target="--ratio 0.1"
  case $opt in --ratio|--faces|--vertices|--auto|--max-factor|--max-error) target="" ;; esac
  name=${opt#--}
  # In core.
  # shellcheck disable=SC2086
  "$bin" "$in" "$out/$name-core.ply" $target $a --quiet >/dev/null 2>"$out/$name-core.err" ||
    { fail "$opt in core: $(cat "$out/$name-core.err")"; continue; }
  core_changed=1
  cmp -s "$out/$name-core.ply" "$out/base-core.ply" && core_changed=0
  # Tiled.
  start=$(date +%s%N)
  # shellcheck disable=SC2086
  "$bin" "$in" "$out/$name-tiled.ply" $target $a --memory 1M --quiet >/dev/null 2>"$out/$name-tiled.err"
  code=$? ms=$((($(date +%s%N) - start) / 1000000))
  if [ $code -eq 2 ]; then
    # Refused: before any work, by name, nothing left behind.
    if grep -q -- "$opt" "$out/$name-tiled.err" && [ "$(wc -l <"$out/$name-tiled.err")" -eq 1 ] &&
      [ ! -e "$out/$name-tiled.ply" ] && [ -z "$(ls -d "$out"/vrsimplify-tiles-* 2>/dev/null)" ] && [ $ms -lt 2000 ]; then
      ok
    else
      fail "$opt tiled: a refusal that is not one line naming it before any work ($ms ms): $(cat "$out/$name-tiled.err")"
    fi
  elif [ $code -eq 0 ]; then
    tiled_changed=1
    cmp -s "$out/$name-tiled.ply" "$out/base-tiled.ply" && tiled_changed=0
    if [[ $same_output == *" $opt "* ]]; then
      [ $tiled_changed -eq 0 ] && ok || fail "$opt tiled changed the output (it is about the run only)"
    elif [ $core_changed -eq 1 ] && [ $tiled_changed -eq 0 ]; then
      fail "$opt changes the output in core but is ignored tiled"
    else
      ok
    fi
  else
    fail "$opt tiled: exit $code: $(cat "$out/$name-tiled.err")"
  fi
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
