#!/usr/bin/env bash
# Sets up, builds and runs every test: the Release build in build/ (core, CLI, the sweep over
# the real meshes, and the plugin in every host: MeshLab 2020.09's meshlabserver and GUI, the
# real MeshLab 2022.02 and 2025.07 GUIs in Debian trixie and sid roots, pymeshlab; the Debian
# packages installed with apt-get); then, the wheel in a fresh virtual environment (with the
# examples the README and the documentation show) and the documentation site in a lane beside
# the sanitizer builds (its log printed when they are done): the core, CLI
# and sweep tests again built with AddressSanitizer + UndefinedBehaviorSanitizer in build/asan/
# (MeshLab cannot load an instrumented plugin), the thread, parts, fan-split and set-up tests under
# ThreadSanitizer in build/tsan/, then a bounded libFuzzer run (VRS_FUZZ_SECONDS, default 120,
# from a fixed seed, VRS_FUZZ_SEED, default 1, so that a run judges the change and not the
# draw; scripts/fuzz.sh alone draws a new seed each time and runs longer, to find what is new).
#   scripts/test.sh [--no-sanitizers]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
# Each stage with the time it starts: where a slow run spent its time.
stage() { echo "== [$(date +%T)] $*"; }
stage "set-up"
"$top/scripts/setup.sh" --roots
stage "the Release build"
"$top/scripts/build.sh" -DVRS_BUILD_TESTS=ON
stage "the Release tests"
# One test more than the cores: the browser and GUI tests wait on throttled servers and
# displays, and another test uses the core meanwhile.
(cd "$top/build" && ctest --output-on-failure -j "$(($(nproc) + 1))")
python_lane() {
  stage "the Python package: the wheel built, installed in a fresh virtual environment, tested"
  "$top/scripts/test_wheel.sh"
  stage "the documentation site, built with --strict"
  "$top/scripts/docs.sh"
}
if [ "${1:-}" = "--no-sanitizers" ]; then
  python_lane
else
  # The wheels and the site in a lane of their own beside the sanitizer builds: pip, the venvs
  # and one pytest process at a time kept one core of two busy (20 of the 85 minutes of a run on
  # a fresh, slow machine). Its own session, so that a failure here stops all of it.
  export -f python_lane stage
  export top
  setsid -w bash -c "set -euo pipefail; python_lane" >"$top/build/python-lane.log" 2>&1 &
  lane=$!
  trap 'kill -- -$lane 2>/dev/null || true' EXIT
  stage "the same tests under AddressSanitizer + UndefinedBehaviorSanitizer"
  # Line tables only (-g1): a sanitizer's report still names file and line, and the two builds
  # compile a quarter faster than with full debug information.
  lines_only=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG")
  cmake -S "$top" -B "$top/build/asan" "${lines_only[@]}" -DVRS_SANITIZE=ON \
    -DVRS_BUILD_TESTS=ON -DVRS_BUILD_PLUGIN=OFF -DVRS_BUILD_BENCH=OFF >/dev/null
  cmake --build "$top/build/asan" -j "$(nproc)"
  # One thread against two and eight, as under ThreadSanitizer: the Release run compares three.
  (cd "$top/build/asan" && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    VRS_TEST_THREAD_COUNTS=2,8 ctest --output-on-failure -j "$(nproc)")
  stage "the worker threads under ThreadSanitizer"
  cmake -S "$top" -B "$top/build/tsan" "${lines_only[@]}" -DVRS_TSAN=ON \
    -DVRS_BUILD_TESTS=ON -DVRS_BUILD_TOOLS=OFF -DVRS_BUILD_PLUGIN=OFF -DVRS_BUILD_BENCH=OFF >/dev/null
  cmake --build "$top/build/tsan" --target test_threads test_parts test_fan_split test_setup_threads test_bucket_queue \
    test_input_surface -j "$(nproc)"
  # One thread against two and eight (not three too: each run is 20 times slower here).
  tsan() { VRS_TEST_THREAD_COUNTS=2,8 TSAN_OPTIONS=halt_on_error=1 "$top/build/tsan/bin/$1" "${@:2}"; }
  # In two lanes side by side, the two long ones (5 minutes each) apart; each lane's log whole.
  (tsan test_threads --gtest_filter='Workers.*:Threads.*' && tsan test_fan_split &&
    tsan test_bucket_queue --gtest_filter='BucketQueue.Fill*' &&
    tsan test_input_surface --gtest_filter='InputSurface.ADeferredBuild*') >"$top/build/tsan/lane1.log" 2>&1 &
  lane1=$!
  (tsan test_parts && tsan test_setup_threads) >"$top/build/tsan/lane2.log" 2>&1 &
  lane2=$!
  status1=0 status2=0
  wait $lane1 || status1=$?
  wait $lane2 || status2=$?
  cat "$top/build/tsan/lane1.log" "$top/build/tsan/lane2.log"
  [ $status1 -eq 0 ] && [ $status2 -eq 0 ] || { echo "ThreadSanitizer: a lane failed"; exit 1; }
  status=0
  wait $lane || status=$?
  trap - EXIT
  cat "$top/build/python-lane.log"
  [ $status -eq 0 ] || { echo "the Python package or the documentation failed (exit $status)"; exit 1; }
  stage "libFuzzer on the core, ${VRS_FUZZ_SECONDS:-120} s"
  VRS_FUZZ_SEED=${VRS_FUZZ_SEED:-1} "$top/scripts/fuzz.sh" "${VRS_FUZZ_SECONDS:-120}"
fi
