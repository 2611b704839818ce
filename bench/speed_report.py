#!/usr/bin/env python3
"""bench/speed.csv -> bench/SPEED.md: medians of alternated runs, ratios to meshoptimizer.

usage: speed_report.py CSV OUT.md
"""
import csv
import datetime
import os
import statistics
import sys
from collections import defaultdict

METHODS = ["ours", "ours-t2", "meshopt", "qecd"]


def machine():
    cpu = "?"
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            cpu = line.split(":", 1)[1].strip()
            break
    mem = 0
    for line in open("/proc/meminfo"):
        if line.startswith("MemTotal"):
            mem = int(line.split()[1]) / 1048576
    return f"{os.cpu_count()} cores, {mem:.0f} GiB, {cpu}"


def main(src, dst):
    runs = defaultdict(lambda: defaultdict(list))  # mesh -> method -> [(s, mb)]
    faces = {}
    for r in csv.DictReader(open(src)):
        if not r["seconds"]:
            continue
        runs[r["mesh"]][r["method"]].append((float(r["seconds"]), float(r["peak_mb"])))
        faces[r["mesh"]] = int(r["input_faces"])
    med = lambda xs, i: statistics.median(x[i] for x in xs) if xs else None
    fmt = lambda x, f="{:.2f}": f.format(x) if x is not None else "—"
    out = [
        "# Speed and memory",
        "",
        f"Measured {datetime.date.today()} on {machine()} by `scripts/bench_speed.sh` "
        "(data: `bench/speed.csv`). At 10 % of the input faces; each method a child process "
        "of `vrs_bench`, ours, ours on 2 threads (`ours-t2`) and meshoptimizer alternated, "
        "medians of their runs (n = runs each); QECD (MeshLab's Quadric Edge Collapse, "
        "dialog defaults) once. Time is the simplification call; memory the process's "
        "resident high-water mark.",
        "",
        "| mesh | input faces | n | ours s | ours-t2 s | meshopt s | QECD s | ours ÷ meshopt "
        "| ours-t2 ÷ meshopt | ours ÷ ours-t2 | µs per input face (ours / t2 / meshopt) "
        "| peak MB (ours / t2 / meshopt / QECD) |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    per_face = []
    for mesh in sorted(runs, key=lambda m: faces[m]):
        m = runs[mesh]
        t = {k: med(m[k], 0) for k in METHODS}
        mb = {k: med(m[k], 1) for k in METHODS}
        ratio = lambda a, b: t[a] / t[b] if t[a] and t[b] else None
        us = {k: t[k] * 1e6 / faces[mesh] if t[k] else None for k in METHODS}
        per_face.append((mesh, faces[mesh], us))
        out.append(
            f"| {mesh} | {faces[mesh]} | {len(m['ours'])} | {fmt(t['ours'], '{:.3f}')} "
            f"| {fmt(t['ours-t2'], '{:.3f}')} | {fmt(t['meshopt'], '{:.3f}')} "
            f"| {fmt(t['qecd'], '{:.3f}')} | **{fmt(ratio('ours', 'meshopt'))}** "
            f"| **{fmt(ratio('ours-t2', 'meshopt'))}** | {fmt(ratio('ours', 'ours-t2'))} "
            f"| {fmt(us['ours'])} / {fmt(us['ours-t2'])} / {fmt(us['meshopt'])} "
            f"| {fmt(mb['ours'], '{:.0f}')} / {fmt(mb['ours-t2'], '{:.0f}')} / "
            f"{fmt(mb['meshopt'], '{:.0f}')} / {fmt(mb['qecd'], '{:.0f}')} |")
    if len(per_face) > 1 and per_face[0][2]["ours"]:
        lo, hi = per_face[0], per_face[-1]
        out += ["", f"Time per input face, {hi[0]} ({hi[1]} faces) over {lo[0]} ({lo[1]}): "
                + ", ".join(f"{k} {hi[2][k] / lo[2][k]:.2f}x" for k in ("ours", "ours-t2", "meshopt")
                            if hi[2][k] and lo[2][k]) + "."]
    open(dst, "w").write("\n".join(out) + "\n")


if __name__ == "__main__":
    main(*sys.argv[1:3])
