#!/usr/bin/env bash
# Where the time goes: Linux perf on the CLI on one thread, twice: bunny00 Loop-subdivided to
# 1.2 M faces (LEVEL 2; 3: 4.8 M) to 10 %, and the real mesh whose time is the furthest from
# meshoptimizer's in bench/speed_corpus.csv (its worst ratio, scripts/bench_speed_corpus.sh),
# run again and again for enough samples. Writes bench/PROFILE.md: for each, the driver's steps
# and the planning's pieces by inclusive time (call graphs), then the functions by their own time.
#   scripts/profile.sh [LEVEL]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
level=${1:-2}
"$top/scripts/setup.sh" linux-perf
"$top/scripts/build.sh" >/dev/null
inputs=$top/third_party/bench-inputs
mesh=$inputs/bunny_loop$level.ply
mkdir -p "$inputs"
[ -s "$mesh" ] || "$top/build/bin/vrs_bench" --loop "$top/third_party/cgal-data/data/meshes/bunny00.off" \
  "$level" "$mesh" >&2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Own time from frequent plain samples; inclusive time from fewer samples with DWARF stacks.
profile() { # name repeats cli...
  local name=$1 repeats=$2
  shift 2
  local loop="for i in \$(seq $repeats); do \"\$@\" >/dev/null 2>&1; done"
  perf record -q -F 2000 -o "$work/$name-self.data" -- bash -c "$loop" _ "$@" >/dev/null 2>&1
  perf record -q -F 400 --call-graph dwarf,16384 -o "$work/$name-graph.data" -- bash -c "$loop" _ "$@" \
    >/dev/null 2>&1
  perf report -i "$work/$name-self.data" --no-children --sort symbol --stdio --percent-limit 0.8 \
    2>/dev/null >"$work/$name-self.txt"
  perf report -i "$work/$name-graph.data" --children --sort symbol --stdio -g none --percent-limit 0.5 \
    2>/dev/null >"$work/$name-graph.txt"
}
profile bunny 1 "$top/build/bin/vrsimplify" "$mesh" "$work/out.ply" --ratio 0.1 --threads 1 --quiet
faces=$("$top/build/bin/vrs_bench" --info "$mesh" | cut -d' ' -f1)
# The worst ratio of ours (one thread, a quiet machine) to meshoptimizer over the real meshes.
read -r worst worst_ratio worst_times < <(python3 - "$top/bench/speed_corpus.csv" <<'PY'
import csv, sys
t = {}
for r in csv.DictReader(open(sys.argv[1])):
    if r["load"] == "quiet":
        t[(r["set"], r["mesh"], r["ratio"], r["method"])] = float(r["seconds"])
runs = [(t[k] / t[k[:3] + ("meshopt",)], k) for k in t
        if k[3] == "ours" and t.get(k[:3] + ("meshopt",), 0) > 0]
times, (s, m, ratio, _) = max(runs)
print(f"{s}/{m} {ratio} {times:.0f}")
PY
)
worst_file=$("$top/scripts/lib/bench_meshes.sh" --cad |
  awk -v n="/${worst#*/}." '!found && index($0, n) { print; found = 1 }')
profile worst 20 "$top/build/bin/vrsimplify" "$worst_file" "$work/out.ply" --ratio "$worst_ratio" \
  --threads 1 --quiet
worst_faces=$("$top/build/bin/vrs_bench" --info "$worst_file" | cut -d' ' -f1)
python3 - "$work" "$top/bench/PROFILE.md" "$faces" "$worst" "$worst_ratio" "$worst_faces" \
  "$worst_times" <<'PY'
import datetime, os, re, sys
work, out, faces, worst, worst_ratio, worst_faces, worst_times = sys.argv[1:8]
def rows(path):  # (percent, function name without arguments)
    for line in open(path):
        m = re.match(r"\s+([\d.]+)%\s+(?:([\d.]+)%\s+)?\[\.\]\s+(.*?)\s*$", line)
        if m:
            sym = re.split(r"\s{2,}", m.group(3))[0]
            sym = sym.replace("(anonymous namespace)", "anon")  # not an argument list
            yield float(m.group(1)), re.sub(r"\(.*", "", sym)
steps = [  # (label, name prefix): the driver's steps, then the planning's pieces
    ("setup: classify and first prices (`Simplifier::prepare`)", "vrs::Simplifier::prepare"),
    ("the parts' rounds (`run_parts`)", "vrs::Simplifier::run_parts"),
    ("one part's queue in a round (`run_part`)", "vrs::Simplifier::run_part"),
    ("frozen vertices priced after a cut (`price_frozen`)", "vrs::Simplifier::price_frozen"),
    ("the whole queue, the last removals (`run`)", "vrs::Simplifier::run"),
    ("its popped batches planned (`plan_batch`)", "vrs::Simplifier::plan_batch"),
    ("faces rewritten (`rewrite`)", "vrs::Simplifier::rewrite"),
    ("accounting (`account`, serial)", "vrs::Simplifier::account"),
    ("neighbours priced again (`reprice`)", "vrs::Simplifier::reprice"),
    ("the slide after the run (`slide`)", "vrs::Simplifier::slide"),
    ("its fans' choices (`slide_choice`)", "vrs::Simplifier::slide_choice"),
    ("a plan (`Planner::plan`)", "vrs::Planner::plan"),
    ("its exact price (`patch_error`)", "vrs::patch_error"),
    ("its plane (`Evaluator::evaluate`)", "vrs::Evaluator::evaluate"),
    ("the candidates' triangles (`fill_triangles`)", "vrs::fill_triangles"),
    ("those vetted, with their corner faces (`fill_candidate`)", "vrs::fill_candidate"),
    ("the candidates ranked (`drop_height`)", "vrs::drop_height"),
    ("topology vetoes (`veto_topology`)", "vrs::veto_topology"),
    ("shape vetoes (`veto_shape`)", "vrs::veto_shape"),
    ("rings read (`Topology::ring`)", "vrs::Topology::ring"),
]
def section(name, title):
    graph = list(rows(f"{work}/{name}-graph.txt"))
    total = next((p for p, s in graph if s == "vrs::simplify"), None)
    lines = ["", f"## {title}", "",
             "### Inclusive time (DWARF call graphs; % of all samples, reading and writing included"
             + (f"; the simplify call is {total:.1f} %)" if total else ")"), "",
             "| step | % |", "|---|---|"]
    for label, prefix in steps:
        pct = next((p for p, s in graph if s == prefix or s.startswith(prefix + "<")), None)
        lines.append(f"| {label} | {pct:.1f} |" if pct is not None else f"| {label} | < 0.5 |")
    lines += ["", "### Own time (plain samples)", "", "| function | % |", "|---|---|"]
    for pct, sym in list(rows(f"{work}/{name}-self.txt"))[:25]:
        lines.append(f"| `{sym}` | {pct:.1f} |")
    return lines
lines = ["# Profile", "",
         f"{datetime.date.today()}, {os.cpu_count()} cores: `scripts/profile.sh` — Linux perf on "
         "`vrsimplify` on one thread: a large smooth mesh, and the real mesh whose time is the "
         "furthest from meshoptimizer's (`bench/SPEED.md`)."]
lines += section("bunny", f"bunny00 Loop-subdivided ({faces} faces) to 10 %")
lines += section("worst", f"The worst ratio of the real meshes: {worst} ({worst_faces} faces) to "
                 f"{float(worst_ratio):g} of its faces, {worst_times}× meshoptimizer's time in "
                 "`bench/speed_corpus.csv` (run 20 times)")
open(out, "w").write("\n".join(lines) + "\n")
PY
echo "wrote bench/PROFILE.md" >&2
