#!/usr/bin/env python3
"""bench/parts.csv (and the small-parts CSV) -> bench/PARTS.md: what simplification by parts
does to the error, run by run, against one queue from the start.

usage: parts_report.py PARTS.csv OUT.md [SMALL_PARTS.csv]
"""
import csv
import datetime
import hashlib
import os
import subprocess
import sys
from collections import defaultdict

from quality_report import gmean, off, quantile, ratio

TUNING_ALWAYS = {"bunny00", "armadillo", "fandisk", "mushroom", "three_peaks", "elephant"}


def held_out(mesh):  # the quality benchmark's rule, on the mesh the input was subdivided from
    base = mesh.rsplit("_loop", 1)[0]
    return base not in TUNING_ALWAYS and hashlib.sha1(f"cgal/{base}".encode()).digest()[0] % 4 == 0


def summary(label, xs):
    if not xs:
        return f"| {label} | 0 | | | | | | |"
    return (f"| {label} | {len(xs)} | {quantile(xs, 0.5):.3f} | {gmean(xs):.3f} | "
            f"{quantile(xs, 0.9):.3f} | {min(xs):.3f} | {max(xs):.3f} | {sum(x > 1.02 for x in xs)} |")


def large(path):
    runs = defaultdict(dict)
    for row in csv.DictReader(open(path)):
        if row["output_faces"]:
            runs[(row["mesh"], row["ratio"])][row["method"]] = row
    out = ["## Large meshes: the default (parts) against one queue from the start", "",
           "Data-set meshes Loop-subdivided past the size that is cut (65 536 vertices), one "
           "thread, side by side in one run (`scripts/bench_parts.sh`). Ratios parts ÷ one queue "
           "(error as a fraction of the bounding-box diagonal, symmetric, sampled). The times are one run each, taken beside other work on the machine: speed is measured in `bench/SPEED.md`.", "",
           "| mesh | input faces | ratio | faces (parts / whole) | mean error ratio | max error ratio "
           "| time (parts / whole, s) |", "|---|---|---|---|---|---|---|"]
    mean, mx = defaultdict(list), defaultdict(list)
    for (mesh, r), m in sorted(runs.items(), key=lambda kv: (kv[0][0], -float(kv[0][1]))):
        p, w = m.get("ours"), m.get("ours-whole")
        if not (p and w):
            continue
        a, b = ratio(p["error_mean"], w["error_mean"]), ratio(p["error_max"], w["error_max"])
        tag = " (held out)" if held_out(mesh) else ""
        out.append(f"| {mesh}{tag} | {p['input_faces']} | {float(r):.0%} | {p['output_faces']} / "
                   f"{w['output_faces']} | {a:.3f} | {b:.3f} | {float(p['seconds']):.2f} / "
                   f"{float(w['seconds']):.2f} |")
        for key in ("all", r):
            mean[key].append(a)
            mx[key].append(b)
    out += ["", "| runs | n | median | gmean | p90 | best | worst | > 1.02 |", "|---|---|---|---|---|---|---|---|"]
    for key in ["all", "0.5", "0.1", "0.01"]:
        name = "all ratios" if key == "all" else f"{float(key):.0%}"
        out.append(summary(f"mean error, {name}", mean[key]))
        out.append(summary(f"max error, {name}", mx[key]))
    return out


def small(path, here):
    runs = defaultdict(dict)
    for row in csv.DictReader(open(path)):
        if row["output_faces"]:
            runs[(row["set"], row["mesh"], row["ratio"])][row["method"]] = row
    out = ["", "## Every kind of mesh, cut into small parts", "",
           "The quality benchmark's tuning meshes (111 meshes, 333 runs; none is large enough to be "
           "cut at the default size) run with parts of 256 and 1024 vertices, against the "
           "default's rows of the same run: a stress test of the design (many frozen borders) on "
           "CAD parts, open borders and scans.", "",
           "| parts of | runs | mean error ratio: median / gmean / p90 / worst | max error ratio: "
           "median / gmean / p90 / worst | off target (parts / default) |", "|---|---|---|---|---|"]
    for method in sorted({m for r in runs.values() for m in r if m.startswith("ours-part")}):
        keys = [k for k in runs if method in runs[k] and "ours" in runs[k]]
        a = [ratio(runs[k][method]["error_mean"], runs[k]["ours"]["error_mean"]) for k in keys]
        b = [ratio(runs[k][method]["error_max"], runs[k]["ours"]["error_max"]) for k in keys]
        offs = sum(off(runs[k][method]) for k in keys), sum(off(runs[k]["ours"]) for k in keys)
        out.append(f"| {method[9:]} | {len(keys)} | {quantile(a, 0.5):.3f} / {gmean(a):.3f} / "
                   f"{quantile(a, 0.9):.2f} / {max(a):.2f} | {quantile(b, 0.5):.3f} / {gmean(b):.3f} "
                   f"/ {quantile(b, 0.9):.2f} / {max(b):.2f} | {offs[0]} / {offs[1]} |")
    ref = os.path.join(here, "quality.csv")
    if os.path.exists(ref):
        tail = subprocess.run([sys.executable, os.path.join(here, "variant_tail.py"), ref, path],
                              capture_output=True, text=True, check=True).stdout.strip()
        out += ["", "The tail against QECD (`bench/variant_tail.py`, QECD's rows from "
                "`bench/quality.csv`): per-run mean-error ratio to QECD.", "", tail]
    return out


def main(src, dst, small_csv=None):
    here = os.path.dirname(os.path.abspath(__file__))
    out = ["# Simplification by parts: the error", "",
           f"Measured {datetime.date.today()} by `scripts/bench_parts.sh` (data: `bench/parts.csv`"
           + (", `bench/parts_small.csv`" if small_csv else "") + ").", ""]
    out += large(src)
    if small_csv:
        out += small(small_csv, here)
    open(dst, "w").write("\n".join(out) + "\n")


if __name__ == "__main__":
    main(*sys.argv[1:4])
