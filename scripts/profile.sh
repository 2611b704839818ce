#!/usr/bin/env bash
# Where the time goes: Linux perf on the CLI simplifying bunny00 Loop-subdivided to 1.2 M faces
# (LEVEL 2; 3: 4.8 M) to 10 % on one thread. Writes bench/PROFILE.md: the driver's steps and the
# planning's pieces by inclusive time (call graphs), then the functions by their own time.
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
cli=("$top/build/bin/vrsimplify" "$mesh" "$work/out.ply" --ratio 0.1 --threads 1 --quiet)
# Own time from frequent plain samples; inclusive time from fewer samples with DWARF stacks.
perf record -q -F 2000 -o "$work/self.data" -- "${cli[@]}" >/dev/null 2>&1
perf record -q -F 400 --call-graph dwarf,16384 -o "$work/graph.data" -- "${cli[@]}" >/dev/null 2>&1
perf report -i "$work/self.data" --no-children --sort symbol --stdio --percent-limit 0.8 \
  2>/dev/null >"$work/self.txt"
perf report -i "$work/graph.data" --children --sort symbol --stdio -g none --percent-limit 0.5 \
  2>/dev/null >"$work/graph.txt"
faces=$("$top/build/bin/vrs_bench" --info "$mesh" | cut -d' ' -f1)
python3 - "$work/self.txt" "$work/graph.txt" "$top/bench/PROFILE.md" "$faces" <<'PY'
import datetime, os, re, sys
self_txt, graph_txt, out, faces = sys.argv[1:5]
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
graph = list(rows(graph_txt))
total = next((p for p, s in graph if s == "vrs::simplify"), None)
lines = ["# Profile", "",
         f"{datetime.date.today()}, {os.cpu_count()} cores: `scripts/profile.sh` — Linux perf on "
         f"`vrsimplify` simplifying bunny00 Loop-subdivided ({faces} faces) to 10 % on one thread.",
         "", "## Inclusive time (DWARF call graphs; % of all samples, reading and writing included)", "",
         "| step | % |", "|---|---|"]
if total:
    lines[-3] = lines[-3].replace("included)", f"included; the simplify call is {total:.1f} %)")
for label, prefix in steps:
    pct = next((p for p, s in graph if s == prefix or s.startswith(prefix + "<")), None)
    lines.append(f"| {label} | {pct:.1f} |" if pct is not None else f"| {label} | < 0.5 |")
lines += ["", "## Own time (plain samples)", "", "| function | % |", "|---|---|"]
for pct, sym in list(rows(self_txt))[:25]:
    lines.append(f"| `{sym}` | {pct:.1f} |")
open(out, "w").write("\n".join(lines) + "\n")
PY
echo "wrote bench/PROFILE.md" >&2
