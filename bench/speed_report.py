#!/usr/bin/env python3
"""bench/speed.csv -> bench/SPEED.md: medians of alternated runs, ratios to meshoptimizer.

usage: speed_report.py CSV OUT.md [SERIAL.csv [CEILING.csv]]
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
        "## The Loop-subdivided bunny, 75 k to 19.3 M faces",
        "",
        f"Measured {datetime.date.today()} on {machine()} by `scripts/bench_speed.sh` "
        "(data: `bench/speed.csv`). At 10 % of the input faces; each method a child process "
        "of `vrs_bench`, ours, ours on 2 threads (`ours-t2`) and meshoptimizer alternated "
        "(each repeat in another of their orders), "
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
    out += targets(runs, faces, per_face, med)
    # The real meshes' section (bench/speed_corpus_report.py) stays where it was, first.
    corpus = ""
    if os.path.exists(dst):
        old = open(dst).read()
        if CORPUS_BEGIN in old and CORPUS_END in old:
            corpus = old[old.index(CORPUS_BEGIN):old.index(CORPUS_END) + len(CORPUS_END)] + "\n\n"
    out[1:1] = ["", corpus.rstrip("\n")] if corpus else []  # before the bunny's section
    open(dst, "w").write("\n".join(out) + "\n")


CORPUS_BEGIN = "<!-- real meshes: bench/speed_corpus_report.py -->"
CORPUS_END = "<!-- end of real meshes -->"


def targets(runs, faces, per_face, med):
    """Issue 31's figures, each met or missed, and what two cores say about sixteen."""
    out = ["", "## Targets", "", "| figure | measured | target | |", "|---|---|---|---|"]
    t = lambda mesh, k: med(runs[mesh][k], 0) if runs[mesh][k] else None
    mb = lambda mesh, k: med(runs[mesh][k], 1) if runs[mesh][k] else None

    def row(what, value, goal, ok):  # ok None: shown, not judged
        verdict = "—" if ok is None else "met" if ok else "**missed**"
        out.append(f"| {what} | {value} | {goal} | {verdict} |")

    for mesh in sorted(runs, key=lambda m: faces[m]):
        one, two, mo = t(mesh, "ours"), t(mesh, "ours-t2"), t(mesh, "meshopt")
        if not (one and two and mo):
            continue
        if faces[mesh] >= 1_000_000:
            row(f"{mesh}: 2 threads ÷ meshoptimizer", f"{two / mo:.2f}", "≤ 1.5", two / mo <= 1.5)
            row(f"{mesh}: 1 thread ÷ meshoptimizer", f"{one / mo:.2f}", "≤ 2.5", one / mo <= 2.5)
        elif faces[mesh] < 100_000:
            row(f"{mesh}: 1 thread ÷ meshoptimizer", f"{one / mo:.2f}", "≤ 3.0", one / mo <= 3.0)
        m1, m2 = mb(mesh, "ours"), mb(mesh, "meshopt")
        judged = faces[mesh] >= 300_000  # the memory target starts there
        row(f"{mesh}: peak memory ÷ meshoptimizer's", f"{m1 / m2:.2f}",
            "≤ 1.0" if judged else "none under 300 k faces", m1 <= m2 if judged else None)
    if len(per_face) > 1 and per_face[0][2]["ours"] and per_face[-1][2]["ours"]:
        lo, hi = per_face[0], per_face[-1]
        growth = hi[2]["ours"] / lo[2]["ours"]
        row(f"time per input face, {lo[1]} → {hi[1]} faces (1 thread)", f"×{growth:.2f}",
            "≤ ×1.25 (goal flat)", growth <= 1.25)
    notes = []
    for mesh in sorted(runs, key=lambda m: faces[m]):
        if faces[mesh] < 1_000_000 or not (t(mesh, "ours") and t(mesh, "ours-t2")):
            continue
        one, two = t(mesh, "ours"), t(mesh, "ours-t2")
        row(f"{mesh}: 2 threads ÷ 1 thread speed-up", f"{one / two:.2f}", "≥ 1.9", one / two >= 1.9)
        # Amdahl: T2 = T1 (s + (1 - s) / 2) gives the serial fraction s.
        s = max(0.0, min(1.0, 2 * two / one - 1))
        notes += ["", f"Serial fraction from the two thread counts on {mesh} (Amdahl, "
                  f"T2 = T1·(s + (1 − s)/2)): s = {s:.2f}, so 16 cores would give at most "
                  f"{1 / (s + (1 - s) / 16):.1f}× one thread (8 cores: {1 / (s + (1 - s) / 8):.1f}×)."]
    out += notes
    return out


def serial_section(path):
    """The run's own account (vrs_bench --serial, one thread): Amdahl from it, and by chunks."""
    out = ["", "## Serial part, as the run measures it", "",
           "One thread, `vrs_bench --serial`: the wall time outside the loops the workers share "
           "(set-up steps, the rounds' bookkeeping, the whole queue's accounting in queue order, "
           "compaction) over the run. Amdahl's projection from it assumes the rest divides evenly "
           "over the cores. **By chunks** does not: each loop's time is split into the chunks its "
           "threads take in turn (grain items, or one range a thread), and 8 or 16 threads take "
           "ceil(chunks / threads) rounds of the mean chunk, so a loop of one chunk (a batch of a "
           "few plans) stays on one thread and a loop of 20 chunks takes two rounds on 16. A loop "
           "of long chunks (50 us or more: the parts' rounds) is timed chunk by chunk and its "
           "chunks handed in order to whichever thread is free first, as the workers do (the "
           "parts dearest first). Memory bandwidth and the machine's own loss (below) take "
           "more; the target is judged by chunks.", "",
           "| mesh | run s | in shared loops s | serial fraction | Amdahl 8 / 16 cores | by chunks 8 / 16 cores | target (16) | |",
           "|---|---|---|---|---|---|---|---|"]
    for row in csv.DictReader(open(path)):
        s = float(row["serial_fraction"])
        p8, p16 = 1 / (s + (1 - s) / 8), 1 / (s + (1 - s) / 16)
        c8, c16 = (float(row[k]) if row.get(k) else None for k in ("by_chunks_8", "by_chunks_16"))
        judged = c16 if c16 is not None else p16
        chunks = f"{c8:.1f}× / {c16:.1f}×" if c16 is not None else "—"
        out.append(f"| {row['mesh']} | {float(row['seconds']):.2f} | {float(row['parallel_seconds']):.2f} "
                   f"| {s:.3f} | {p8:.1f}× / {p16:.1f}× | {chunks} | ≥ 12× | {'met' if judged >= 12 else '**missed**'} |")
    return out


def ceiling_section(path):
    """Two one-thread runs at once against one alone: what two threads can get here at best."""
    rows = defaultdict(list)
    for row in csv.DictReader(open(path)):
        rows[row["mesh"]].append(row)
    out = ["", "## What two threads can get on this machine", "",
           "`vrs_bench --serial`, bunny00 Loop-subdivided to 10 %, in turn: one thread alone, two "
           "one-thread runs at once (they share nothing: no memory, no work), one run on two "
           "threads; medians. Two independent runs each taking longer than one alone is the "
           "machine's own loss (shared caches, memory, a host's other guests); 2 × alone ÷ pair is "
           "then the most two threads can give, and the run's scaling is judged against it too.", "",
           "| mesh | n | one alone s | each of two at once s | two threads s | ceiling | scaling | of the ceiling | target ≥ 1.9× |",
           "|---|---|---|---|---|---|---|---|---|"]
    med = statistics.median
    for mesh, rs in rows.items():
        alone = med(float(r["alone"]) for r in rs)
        pair = med(x for r in rs for x in (float(r["pair_a"]), float(r["pair_b"])))
        two = med(float(r["two_threads"]) for r in rs)
        ceil, scale = 2 * alone / pair, alone / two
        out.append(f"| {mesh} | {len(rs)} | {alone:.2f} | {pair:.2f} | {two:.2f} | {ceil:.2f}× "
                   f"| {scale:.2f}× | {100 * scale / ceil:.0f} % | {'met' if scale >= 1.9 else '**missed**'} |")
    return out


if __name__ == "__main__":
    main(*sys.argv[1:3])
    extra = []
    if len(sys.argv) > 3 and os.path.exists(sys.argv[3]):
        extra += serial_section(sys.argv[3])
    if len(sys.argv) > 4 and os.path.exists(sys.argv[4]):
        extra += ceiling_section(sys.argv[4])
    if extra:
        with open(sys.argv[2], "a") as f:
            f.write("\n".join(extra) + "\n")
