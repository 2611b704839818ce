#!/usr/bin/env bash
# Error, targets and fold-overs over whole data sets, not the six meshes the benchmark tunes on:
# every mesh of CGAL's data set and every OBJ/PLY/STL/OFF model of assimp's test models (Debian
# packages) of at least 200 faces, and the CAD data set (bench/cad/make_parts.py: parts modelled in
# build123d, exported to STL), at 50 %, 10 % and 1 %. Methods, side by side in one run:
# the default ("ours"), the boundary simplified ("ours-boundary", for the open meshes, as QECD
# does), the paper's factor ("ours-factor"), the vertex-keeping class (MeshLab's QECD with
# optimal placement off, OpenMesh's decimater with its quadric module, meshoptimizer,
# vtkDecimatePro), MeshLab's QECD with its defaults (the yardstick), with Preserve Topology and
# at the face count each vertex keeper ends with (qecd-at-ours, qecd-at-openmesh, ...: the
# yardstick where that method stops short of the target),
# and the core of BASELINE (default: ea2b941, main before the relaxed passes answered to the input; built once into
# $VRS_CACHE). One job per core (meshes shared out), one thread per run. Writes
# bench/quality.csv and bench/QUALITY.md (bench/quality_report.py: medians and clamped
# geometric means, the class table, the held-out meshes apart, the worst runs).
#   scripts/bench_quality.sh [--samples S] [--baseline COMMIT] [--methods M,..] [--tuning]
#                            [--csv FILE | --merge] [--ratios R,..] [--only NAME...]
# --tuning skips the held-out meshes (what a tuning loop may run on); --methods and --csv (a
# scratch CSV, no report) are for such loops. --merge runs --methods alone and puts their rows
# in place of those methods' rows in bench/quality.csv, then writes the report (the other
# methods' rows, same samples, as they were measured).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cache=${VRS_CACHE:-/var/cache/vrsimplify}
samples=30000 baseline=ea2b941 only=() tuning=0 csv="" \
  methods=ours,ours-boundary,ours-factor,qecd,qecd-topology,qecd-keep,qecd-at-ours,qecd-at-ours-boundary,openmesh,qecd-at-openmesh,meshopt,qecd-at-meshopt,vtk
merge=0 ratios=0.5,0.1,0.01
while [ $# -gt 0 ]; do
  case $1 in
  --samples) samples=$2; shift 2 ;;
  --baseline) baseline=$2; shift 2 ;;
  --methods) methods=$2; shift 2 ;;
  --tuning) tuning=1; shift ;;
  --csv) csv=$2; shift 2 ;;
  --merge) merge=1; shift ;;
  --ratios) ratios=$2; shift 2 ;;
  --only) shift; only=("$@"); break ;;
  *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
"$top/scripts/setup.sh"
"$top/scripts/build.sh" >/dev/null
bench=${VRS_BENCH:-$top/build/bin/vrs_bench} # VRS_BENCH: a prebuilt one (comparing builds)

# The baseline's benchmark, from its own sources (a detached worktree beside the cache). "--baseline none": no baseline.
base=""
if [ "$baseline" != none ]; then
  base_dir=$cache/baseline-$baseline
  if [ ! -x "$base_dir/build/bin/vrs_bench" ]; then
    rm -rf "$base_dir"
    git -C "$top" worktree prune
    git -C "$top" worktree add --detach "$base_dir" "$baseline" >/dev/null
    ln -s "$top/third_party" "$base_dir/third_party"
    cmake -S "$base_dir" -B "$base_dir/build" -DCMAKE_BUILD_TYPE=Release -DVRS_BUILD_BENCH=ON \
      -DVRS_BUILD_TESTS=OFF >/dev/null
    cmake --build "$base_dir/build" --target vrs_bench -j "$(nproc)" >/dev/null
  fi
  base=$base_dir/build/bin/vrs_bench
fi

files=()
while IFS= read -r f; do files+=("$f"); done < <("$top/scripts/lib/bench_meshes.sh" --cad)
report=0
[ -n "$csv" ] || { csv=$top/bench/quality.csv; report=1; }
[ "$merge" -eq 0 ] || { [ "$csv" = "$top/bench/quality.csv" ] || { echo "--merge writes bench/quality.csv: no --csv" >&2; exit 2; }; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
header="set,mesh,input_faces,open,ratio,target_faces,method,output_faces,output_vertices,seconds,error_max,error_mean,fold_area,note"
one_mesh() { # file scratch-dir: its rows on stdout
  local f=$1 scratch=$2 name set_name info faces open
  name=$(basename "$f"); name=${name%.*}
  case $f in /usr/share/assimp/*) set_name=assimp ;; */cad-parts-*) set_name=cad ;; *) set_name=cgal ;; esac
  # One model in several formats (assimp's Wuson .off/.ply/.stl): each run keeps its own name.
  [ "$set_name" != assimp ] || [ "$(printf '%s\n' "${files[@]}" | grep -c "^/usr/share/assimp/.*/$name\.[^/]*$")" -le 1 ] ||
    name=$name-${f##*.}
  # CGAL's too (pig.off and pig.stl are two meshes; sphere.off/.ply/.stl one in three formats):
  # the .off keeps the plain name (the held-out choice hashes it), the others are suffixed.
  [ "$set_name" != cgal ] || [ "${f##*.}" = off ] || [ "$(printf '%s\n' "${files[@]}" | grep -c "cgal-data/.*/$name\.[^/]*$")" -le 1 ] ||
    name=$name-${f##*.}
  if [ ${#only[@]} -gt 0 ] && ! printf '%s\n' "${only[@]}" | grep -qx "$name"; then return; fi
  if [ "$tuning" -eq 1 ] && python3 -c 'import hashlib,sys; s,m=sys.argv[1:3]; sys.exit(0 if m not in {"bunny00","armadillo","fandisk","mushroom","three_peaks","elephant"} and hashlib.sha1(f"{s}/{m}".encode()).digest()[0] % 4 == 0 else 1)' "$set_name" "$name"; then
    return 0 # held out: never in a tuning loop (bench/quality_report.py names them)
  fi
  info=$("$bench" --info "$f" 2>/dev/null) || return 0 # unreadable, or not a triangle mesh
  read -r faces open <<<"$info"
  [ "$faces" -ge 200 ] || return 0
  echo "== $set_name $name ($faces faces)" >&2
  rm -f "$scratch"/*.ply
  {
    "$bench" "$f" --name "$name" --samples "$samples" --ratios "$ratios" \
      --methods "$methods" 2>/dev/null || true
    # The baseline's rows get their fold-over share from today's measure (same samples).
    [ -z "$base" ] || "$base" "$f" --name "$name" --samples "$samples" --methods ours --save "$scratch" 2>/dev/null |
      while IFS=, read -r m fa r t _ of ov s pk ex emax emean erms note; do
        folds=$("$bench" --compare "$f" "$scratch/${name}_${r}_ours.ply" --samples "$samples" | cut -d' ' -f4)
        echo "$m,$fa,$r,$t,baseline,$of,$ov,$s,$pk,$ex,$emax,$emean,$erms,$folds,$note"
      done || true
  } | awk -F, -v s="$set_name" -v o="$open" 'NF >= 14 {
        printf "%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n", s, $1, $2, o, $3, $4, $5, $6, $7, $8, $11, $12, $14, $15 }'
}
jobs=$(nproc)
for j in $(seq 0 $((jobs - 1))); do
  mkdir -p "$work/$j"
  (
    i=0
    for f in "${files[@]}"; do
      [ $((i++ % jobs)) -eq "$j" ] && one_mesh "$f" "$work/$j"
    done >"$work/rows.$j"
  ) &
done
wait
if [ "$merge" -eq 1 ]; then # the other methods' rows as they were, these methods' new ones
  awk -F, -v m="$methods" 'BEGIN { n = split(m, a, ","); for (i = 1; i <= n; i++) new[a[i]] = 1 }
    NR > 1 && !($7 in new)' "$csv" >"$work/kept"
  { echo "$header"; sort -t, -k1,2 -k5,5r -s "$work"/rows.* "$work/kept"; } >"$work/merged"
  mv "$work/merged" "$csv"
else
  { echo "$header"; sort -t, -k1,2 -k5,5r -s "$work"/rows.*; } >"$csv"
fi
if [ "$report" -eq 1 ]; then
  # The ten worst runs of ours, rendered beside QECD (bench/renders/worst/).
  python3 "$top/bench/render_worst.py" "$csv" "$top/bench/renders/worst" "$bench" \
    "$top/build/bin/vrs_render" "$top/scripts/lib/on_display.sh" 10
  # What the peers that beat ours in the tail gave up (topology, folds): bench/tail_peers.md.
  python3 "$top/bench/tail_peers.py" "$csv" "$top/bench/tail_peers.md" "$bench"
  python3 "$top/bench/quality_report.py" "$csv" "$top/bench/QUALITY.md" "$baseline"
  echo "wrote $csv and bench/QUALITY.md" >&2
else
  echo "wrote $csv" >&2
fi
