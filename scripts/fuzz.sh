#!/usr/bin/env bash
# Fuzzes the core with libFuzzer (clang 14, ASan + UBSan) for SECONDS (default 600): builds
# build/fuzz/, makes the seed corpus from the shipped meshes and CGAL's small ones, runs.
# A finding is written to build/fuzz/findings/ and the script fails; copy it to
# fuzz/regressions/ (with a name that says what it was) once fixed, and the tests keep it.
#   scripts/fuzz.sh [SECONDS]
set -euo pipefail
seconds=${1:-600}
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/scripts/setup.sh"
b=$top/build/fuzz
cmake -S "$top" -B "$b" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DVRS_SANITIZE=ON -DVRS_BUILD_FUZZ=ON -DVRS_BUILD_TOOLS=OFF >/dev/null
cmake --build "$b" -j "$(nproc)" --target vrs_fuzz vrs_fuzz_seeds >/dev/null
mkdir -p "$b/seeds" "$b/corpus" "$b/findings"
data=$top/third_party/cgal-data/data/meshes
# shellcheck disable=SC2046
"$b/bin/vrs_fuzz_seeds" "$b/seeds" "$top"/meshes/mushroom.off "$top"/meshes/three_peaks.off \
  $(find "$data" -name '*.off' -size -24k | sort) >/dev/null
echo "fuzz: ${seconds} s, corpus $b/corpus, seeds $b/seeds"
"$b/bin/vrs_fuzz" -max_total_time="$seconds" -max_len=65536 -timeout=20 -rss_limit_mb=4096 \
  -print_final_stats=1 -artifact_prefix="$b/findings/" "$b/corpus" "$b/seeds" 2>"$b/fuzz.log" || {
  grep -E "invariant broken|ERROR|runtime error" "$b/fuzz.log" | head -5
  echo "fuzz: a finding, see $b/findings/ and $b/fuzz.log"
  exit 1
}
grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$b/fuzz.log"
grep -E "^#[0-9]+.*(DONE|pulse)" "$b/fuzz.log" | tail -1
echo "fuzz: no finding"
