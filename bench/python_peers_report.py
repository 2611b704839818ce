#!/usr/bin/env python3
"""bench/python_peers.csv -> bench/PYTHON_PEERS.md: what Python users pip-install, beside ours.

usage: python_peers_report.py CSV OUT.md

Errors as ratios to MeshLab's QECD on the same mesh and target (bench/quality.csv), median and
geometric mean of ratios clamped to [0.1, 10], as bench/QUALITY.md (quality_report.py's rules:
the same held-out meshes, the same "off target"). Per ratio, and over all ratios.
"""
import csv
import datetime
import platform
import statistics
import sys
from collections import defaultdict

from quality_report import OVER, SLACK, gmean, held_out, ratio

METHODS = ["vrsimplify", "vrsimplify-boundary", "fast-simplification", "pyfqmr", "meshoptimizer",
           "open3d"]
RATIOS = ["0.5", "0.1", "0.01"]


def pair(values):
    return (statistics.median(values), gmean(values)) if values else (float("nan"),) * 2


def table(rows, title):
    by = defaultdict(list)  # (method, ratio) -> rows
    for r in rows:
        by[(r["method"], r["ratio"])].append(r)
    lines = [f"### {title}", "",
             "| method | ratio | runs | mean error ÷ QECD | max error ÷ QECD | off target | "
             "runs with moved vertices | runs with new non-manifold edges | failed | time ÷ ours |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    ours_time = {(r["set"], r["mesh"], r["input_faces"], r["ratio"]): float(r["seconds"])
                 for r in rows if r["method"] == "vrsimplify" and r["seconds"]}
    for m in METHODS:
        for rat in RATIOS + ["all"]:
            rs = [r for k, v in by.items() if k[0] == m and (rat == "all" or k[1] == rat) for r in v]
            if not rs:
                continue
            done = [r for r in rs if r["output_faces"] and r["error_mean"]]
            mean = pair([ratio(r["error_mean"], r["qecd_error_mean"]) for r in done])
            mx = pair([ratio(r["error_max"], r["qecd_error_max"]) for r in done])
            off = sum(int(r["output_faces"]) > max(OVER * int(r["target_faces"]),
                                                   int(r["target_faces"]) + SLACK) for r in done)
            moved = sum(int(r["moved_vertices"]) > 0 for r in done)
            nm = sum(int(r["new_nonmanifold_edges"]) > 0 for r in done)
            failed = len(rs) - len(done)
            key = lambda r: (r["set"], r["mesh"], r["input_faces"], r["ratio"])  # noqa: E731
            times = [float(r["seconds"]) / ours_time[key(r)] for r in done
                     if ours_time.get(key(r), 0) > 0]
            t = f"{statistics.median(times):.2f}" if times else "n/a"
            lines.append(f"| {m} | {rat} | {len(rs)} | {mean[0]:.3f} / {mean[1]:.3f} | "
                         f"{mx[0]:.3f} / {mx[1]:.3f} | {off} | {moved} | {nm} | {failed} | {t} |")
    return lines + [""]


def worst(rows, n=8):
    """Ours against the best peer on the same run, by how much farther ours is (errors are
    fractions of the diagonal, so near-zero errors of flat parts do not rule the list)."""
    out = ["### Worst runs of ours against the best peer (mean error, % of the diagonal)", ""]
    best = {}
    for r in rows:
        if not r["method"].startswith("vrsimplify") and r["error_mean"]:
            k = (r["set"], r["mesh"], r["input_faces"], r["ratio"])
            if k not in best or float(r["error_mean"]) < float(best[k]["error_mean"]):
                best[k] = r
    ours = [(float(r["error_mean"]) - float(best[k]["error_mean"]), r, best[k]) for r in rows
            if r["method"] == "vrsimplify" and r["error_mean"]
            and (k := (r["set"], r["mesh"], r["input_faces"], r["ratio"])) in best]
    for d, r, b in sorted(ours, key=lambda t: -t[0])[:n]:
        out.append(f"- {r['set']}/{r['mesh']} at {r['ratio']}: ours {100 * float(r['error_mean']):.3g} %"
                   f" ({r['output_faces']} faces for {r['target_faces']}), {b['method']} "
                   f"{100 * float(b['error_mean']):.3g} % ({b['output_faces']} faces)")
    return out + [""]


def main():
    rows = list(csv.DictReader(open(sys.argv[1])))
    meshes = {(r["set"], r["mesh"]) for r in rows}
    held = [r for r in rows if held_out((r["set"], r["mesh"]))]
    rest = [r for r in rows if not held_out((r["set"], r["mesh"]))]
    lines = [
        "# Beside what Python users pip-install",
        "",
        f"`scripts/bench_python_peers.sh`, {datetime.date.today()}, {platform.machine()}, "
        f"{len(meshes)} meshes (CGAL's data set and assimp's test models, ≥ 200 faces), "
        "one thread each, every library through numpy as its documentation shows, the target "
        "its only setting (bench/requirements-peers.txt pins them). Errors: symmetric surface "
        "distance (bench/surface_error.cpp), as ratios to MeshLab's QECD on the same mesh and "
        "target: median / geometric mean of ratios clamped to [0.1, 10]. Off target: more than "
        "5 % and 2 faces over. Moved: some output vertex is not an input vertex. Time ÷ ours: "
        "median over runs of the library's call time over vrsimplify.simplify's (one thread; "
        "its default uses every core). `vrsimplify-boundary`: `simplify_boundary=True`, open "
        "meshes' borders simplified too, as every peer here does by default.",
        "",
    ]
    lines += table(rows, "Whole set")
    lines += table(rest, f"Without the held-out meshes ({len({(r['set'], r['mesh']) for r in rest})})")
    lines += table(held, f"Held-out meshes only ({len({(r['set'], r['mesh']) for r in held})}; "
                         "never in a tuning loop)")
    lines += worst(rows)
    failures = sorted({(r["method"], r["note"]) for r in rows if r["note"].startswith("failed")})
    if failures:
        lines += ["### Failures", ""] + [f"- {m}: {n}" for m, n in failures[:20]] + [""]
    open(sys.argv[2], "w").write("\n".join(lines))


if __name__ == "__main__":
    main()
