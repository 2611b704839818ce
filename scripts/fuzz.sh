#!/usr/bin/env bash
# Fuzzes the core with libFuzzer (clang 14, ASan + UBSan) for SECONDS (default 600): builds
# build/fuzz/, makes the seed corpus from the shipped meshes and CGAL's small ones, runs; then
# the tiled runs' streaming readers (PLY, OBJ) for a quarter of that, seeded with small files.
# A finding is written to build/fuzz/findings/ and the script fails; copy it to
# fuzz/regressions/ (with a name that says what it was) once fixed, and the tests keep it.
# VRS_FUZZ_SEED fixes libFuzzer's seed (default 0: a new one each run).
#   scripts/fuzz.sh [SECONDS]
set -euo pipefail
seconds=${1:-600}
seed=${VRS_FUZZ_SEED:-0}
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/scripts/setup.sh"
b=$top/build/fuzz
cmake -S "$top" -B "$b" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DVRS_SANITIZE=ON -DVRS_BUILD_FUZZ=ON -DVRS_BUILD_TOOLS=OFF >/dev/null
cmake --build "$b" -j "$(nproc)" --target vrs_fuzz vrs_fuzz_seeds vrs_fuzz_stream >/dev/null
mkdir -p "$b/seeds" "$b/corpus" "$b/findings"
data=$top/third_party/cgal-data/data/meshes
# shellcheck disable=SC2046
"$b/bin/vrs_fuzz_seeds" "$b/seeds" "$top"/meshes/mushroom.off "$top"/meshes/three_peaks.off \
  $(find "$data" -name '*.off' -size -24k | sort) >/dev/null
echo "fuzz: ${seconds} s, seed ${seed} (0: drawn), corpus $b/corpus, seeds $b/seeds"
"$b/bin/vrs_fuzz" -seed="$seed" -max_total_time="$seconds" -max_len=65536 -timeout=90 -rss_limit_mb=4096 \
  -print_final_stats=1 -artifact_prefix="$b/findings/" "$b/corpus" "$b/seeds" 2>"$b/fuzz.log" || {
  grep -E "invariant broken|ERROR|runtime error" "$b/fuzz.log" | head -5
  echo "fuzz: a finding, see $b/findings/ and $b/fuzz.log"
  exit 1
}
grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$b/fuzz.log"
grep -E "^#[0-9]+.*(DONE|pulse)" "$b/fuzz.log" | tail -1

# The streaming readers: seeds are small PLY (ascii, binary), OBJ and OFF files, a first byte
# each saying which reader (its value modulo 3: 0 PLY, 1 OBJ, 2 OFF).
s=$b/stream-seeds
mkdir -p "$s" "$b/stream-corpus"
{ printf '\0'; printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n'; } >"$s/ascii.ply"
{ printf '\0'; printf 'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n'
  head -c 36 /dev/zero; printf '\003\000\000\000\000\001\000\000\000\002\000\000\000'; } >"$s/binary.ply"
{ printf '\1'; printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\nvt 0 0\nf 1/1 2/1 3/1 4/1\nf -1 -2 -3\n'; } >"$s/quad.obj"
{ printf '\2'; printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n3 0 1 2 255 0 0\n4 0 1 3 2\n'; } >"$s/colored.off"
stream_seconds=$(( seconds / 4 > 10 ? seconds / 4 : 10 ))
"$b/bin/vrs_fuzz_stream" -seed="$seed" -max_total_time="$stream_seconds" -max_len=4096 -timeout=5 -rss_limit_mb=2048 \
  -print_final_stats=1 -artifact_prefix="$b/findings/" "$b/stream-corpus" "$s" 2>"$b/fuzz-stream.log" || {
  grep -E "ERROR|runtime error" "$b/fuzz-stream.log" | head -5
  echo "fuzz: a finding in the streaming readers, see $b/findings/ and $b/fuzz-stream.log"
  exit 1
}
echo "fuzz (streaming readers): $(grep -E "stat::number_of_executed_units" "$b/fuzz-stream.log" | awk '{print $2}') executions in ${stream_seconds} s"
echo "fuzz: no finding"
