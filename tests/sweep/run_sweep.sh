#!/usr/bin/env bash
# The sweep: every mesh of CGAL's data set (Debian libcgal-demo) and of assimp's test models
# (Debian assimp-testmodels, malformed ones included) at 50 %, 10 % and 1 %, every invariant
# checked by vrs_sweep. One process per file, so that a reader crashing on a malformed file is
# told apart from a crash of ours (a crash after LOADED is ours: a failure).
#   run_sweep.sh VRS_SWEEP CGAL_DATA_DIR OUT_DIR [--ci] [--part K/N]
# --ci: the CGAL meshes under 400 kB and every assimp model (the full set takes longer).
# --part K/N: the K-th of N shares of the files, of about equal bytes (ctest runs them side by
# side).
# VRS_SWEEP_FLAGS: more flags for vrs_sweep (the sanitizer build passes --no-rerun).
set -u
sweep=$1 cgal=$2 out=$3 ci=${4:-} part=1/1
[ "${5:-}" = --part ] && part=${6:-1/1}
share=${part%/*} shares=${part#*/}
mkdir -p "$out"
log=$out/sweep.log
: >"$log"
files=()
while IFS= read -r f; do files+=("$f"); done < <(
  if [ "$ci" = --ci ]; then
    find "$cgal" -maxdepth 1 -type f -size -400k
  else
    find "$cgal" -maxdepth 1 -type f
  fi | sort
  find "$(dirname "$cgal")/points_3" -maxdepth 1 -type f \( -name '*.off' -o -name '*.ply' \) | sort
  find /usr/share/assimp/models -type f | sort)
[ ${#files[@]} -gt 100 ] || { echo "sweep: only ${#files[@]} files: run scripts/setup.sh"; exit 1; }
# Shares of about equal bytes (the time follows the size): the largest file first, each to the
# share holding the fewest bytes so far; then each share in name order.
mine=()
while IFS= read -r f; do mine+=("$f"); done < <(
  for f in "${files[@]}"; do printf '%s\t%s\n' "$(stat -c %s "$f")" "$f"; done | sort -t$'\t' -k1,1nr -k2 |
    awk -F'\t' -v shares="$shares" -v share="$share" '{
      best = 1
      for (k = 2; k <= shares; k++) if (load[k] < load[best]) best = k
      load[best] += $1
      if (best == share) print $2
    }' | sort)
files=("${mine[@]}")

ours_crashed=0 reader_crashed=0
for f in "${files[@]}"; do
  # shellcheck disable=SC2086 # flags, split
  timeout 600 "$sweep" ${VRS_SWEEP_FLAGS:-} "$f" >"$out/one.log" 2>&1
  code=$?
  cat "$out/one.log" >>"$log"
  if [ $code -gt 1 ]; then
    if grep -q "^LOADED " "$out/one.log"; then
      echo "CRASH $f (exit $code) after loading: ours" >>"$log"; ours_crashed=$((ours_crashed + 1))
    else
      echo "READER-CRASH $f (exit $code)" >>"$log"; reader_crashed=$((reader_crashed + 1))
    fi
  fi
done
meshes=$(grep -c "^LOADED " "$log")
runs=$(grep -c "^RUN " "$log")
fails=$(grep -c "^RUN .* FAIL: " "$log")
skips=$(grep -c "^SKIP " "$log")
refused=$(grep -c "^RUN .* refused " "$log")
echo "sweep: ${#files[@]} files; $meshes meshes x ratios = $runs runs, $fails broke an invariant," \
  "$ours_crashed crashed; $refused refused with a message; $skips files skipped" \
  "(not a model format, unreadable or no triangles: $(grep '^SKIP ' "$log" | grep -c 'not a model format') /" \
  "$(grep '^SKIP ' "$log" | grep -c 'unreadable\|assimp:') / $(grep '^SKIP ' "$log" | grep -c 'no triangles'));" \
  "$reader_crashed reader crashes (assimp's, before our code ran). Log: $log"
grep -E "FAIL: |^CRASH " "$log" | head -20
[ "$fails" -eq 0 ] && [ "$ours_crashed" -eq 0 ]
