# Sourced by benchmark scripts (with $top set): sets up and builds, then names the benchmark
# binary ($bench), CGAL's meshes ($data) and the cache of generated inputs ($inputs, outside
# the tracked files).
"$top/scripts/setup.sh"
"$top/scripts/build.sh" >/dev/null
bench=$top/build/bin/vrs_bench
data=$top/third_party/cgal-data/data/meshes
inputs=$top/third_party/bench-inputs
mkdir -p "$inputs"
