#!/usr/bin/env bash
# Speed on the meshes people have: every mesh of the quality set (CGAL's data set, assimp's test
# models, the CAD parts) of at least 5 000 faces, at 50 %, 10 % and 1 %, side by side in one run
# per mesh: ours on one thread ("ours"), ours with the default thread count ("ours-t0": every
# core), meshoptimizer and MeshLab's QECD. Then ours and ours-t0 again while another process
# keeps one core busy (a loaded machine: the default thread count must not be slower than one
# thread; three runs each, their median). One run at a time (timings), the surface error sampled lightly (not the point here).
# Writes bench/speed_corpus.csv and the "Real meshes" section of bench/SPEED.md
# (bench/speed_corpus_report.py).
#   scripts/bench_speed_corpus.sh [--min-faces N] [--only NAME...]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
min_faces=5000 only=()
while [ $# -gt 0 ]; do
  case $1 in
  --min-faces) min_faces=$2; shift 2 ;;
  --only) shift; only=("$@"); break ;;
  *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
"$top/scripts/setup.sh" >/dev/null
"$top/scripts/build.sh" >/dev/null
bench=${VRS_BENCH:-$top/build/bin/vrs_bench}
csv=$top/bench/speed_corpus.csv
work=$(mktemp -d)
busy=""
trap '[ -z "$busy" ] || kill "$busy" 2>/dev/null; rm -rf "$work"' EXIT
echo "set,mesh,input_faces,ratio,target_faces,method,load,output_faces,seconds,error_mean" >"$work/rows"
run() { # file set name load methods
  "$bench" "$1" --name "$3" --samples 2000 --methods "$5" 2>/dev/null |
    awk -F, -v s="$2" -v l="$4" 'NF >= 14 && $8 != "" { printf "%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n", s, $1, $2, $3, $4, $5, l, $6, $8, $12 }' >>"$work/rows"
}
while IFS= read -r f; do
  name=$(basename "$f"); name=${name%.*}
  case $f in /usr/share/assimp/*) set_name=assimp ;; */cad-parts-*) set_name=cad ;; *) set_name=cgal ;; esac
  if [ ${#only[@]} -gt 0 ] && ! printf '%s\n' "${only[@]}" | grep -qx "$name"; then continue; fi
  info=$("$bench" --info "$f" 2>/dev/null) || continue
  read -r faces _ <<<"$info"
  [ "$faces" -ge "$min_faces" ] || continue
  echo "== $set_name $name ($faces faces)" >&2
  run "$f" "$set_name" "$name" quiet ours,ours-t0,meshopt,qecd
  # A loaded machine: one core kept busy by another process while ours runs on one thread and
  # on the default count, three times in turn (the report takes each one's median: a loaded
  # machine's noise between two runs is larger than the difference asked about).
  python3 -c 'while True: pass' &
  busy=$!
  sleep 0.2
  for _ in 1 2 3; do run "$f" "$set_name" "$name" loaded ours,ours-t0; done
  kill "$busy"; wait "$busy" 2>/dev/null || true; busy=""
done < <("$top/scripts/lib/bench_meshes.sh" --cad)
mv "$work/rows" "$csv"
python3 "$top/bench/speed_corpus_report.py" "$csv" "$top/bench/SPEED.md"
echo "wrote $csv and bench/SPEED.md's real meshes" >&2
