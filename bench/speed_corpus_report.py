#!/usr/bin/env python3
"""bench/speed_corpus.csv -> the "real meshes" section of bench/SPEED.md: speed on the meshes
people have.

usage: speed_corpus_report.py CSV SPEED.md

The section goes between the markers BEGIN and END below, right after the report's title (in
place of the one before); bench/speed_report.py keeps it when it writes the rest of SPEED.md.

Ratios of times measured side by side in one run per mesh (the machine's speed swings; the
ratios hold): ours on one thread and on the default thread count against meshoptimizer and
MeshLab's QECD, per ratio, as median, p90 and worst; time per input face by mesh size; and the
default thread count against one thread with another process keeping a core busy.
"""
import csv
import datetime
import os
import platform
import statistics
import sys
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from quality_report import quantile  # noqa: E402  (one quantile for every report)

BEGIN, END = "<!-- real meshes: bench/speed_corpus_report.py -->", "<!-- end of real meshes -->"


def splice(path, section):
    """SPEED.md with `section` between the markers, after its title."""
    text = open(path).read() if os.path.exists(path) else "# Speed and memory\n"
    if BEGIN in text and END in text:
        text = text[:text.index(BEGIN)] + text[text.index(END) + len(END) + 1:]
    title, _, rest = text.partition("\n")
    rest = rest.lstrip("\n")
    open(path, "w").write(f"{title}\n\n{BEGIN}\n{section}{END}\n\n{rest}")


def machine():
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return f"{os.cpu_count()} cores, {line.split(':', 1)[1].strip()}"
    except OSError:
        pass
    return f"{os.cpu_count()} cores, {platform.processor()}"


def main(src, dst):
    runs = defaultdict(dict)  # (set, mesh, ratio) -> (method, load) -> row
    times = defaultdict(list)  # the same run repeated (the loaded ones): its median stands
    for r in csv.DictReader(open(src)):
        if r["seconds"]:
            key = (r["set"], r["mesh"], r["ratio"])
            runs[key].setdefault((r["method"], r["load"]), dict(r))
            times[key + (r["method"], r["load"])].append(float(r["seconds"]))
    for key, row in runs.items():
        for run, r in row.items():
            r["seconds"] = str(statistics.median(times[key + run]))
    ratios = sorted({k[2] for k in runs}, key=float, reverse=True)
    t = lambda m, method, load="quiet": float(m[(method, load)]["seconds"])
    out = [
        "## Real meshes",
        "",
        f"Measured {datetime.date.today()} on {machine()} by `scripts/bench_speed_corpus.sh` "
        f"(data: `bench/speed_corpus.csv`): {len({(k[0], k[1]) for k in runs})} meshes of the quality set "
        "(CGAL's data set, assimp's test models, the CAD parts) of 5 000 faces or more, at "
        + ", ".join(f"{float(r):g}" for r in ratios) + " of the faces. For each mesh, ours on one thread "
        "(`ours`) and with the default thread count (`ours-t0`: every core), meshoptimizer and QECD "
        "run one after the other as child processes of `vrs_bench`; time is the simplification call. "
        "*Loaded*: the same two runs of ours, three times in turn, while another process keeps "
        "one core busy; each one's median.",
        "",
        "### Ratios",
        "",
        "| ratio | runs | ours ÷ meshopt: median | p90 | worst | ours-t0 ÷ meshopt: median | ours ÷ QECD: median | worst | ours slower than QECD | quiet: t0 ÷ one thread, median / worst | loaded: t0 ÷ one thread, median / worst | loaded: runs t0 slower than one thread |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for rt in ratios + ["all"]:
        ms = [m for k, m in runs.items() if (rt == "all" or k[2] == rt)
              and all(x in m for x in [("ours", "quiet"), ("ours-t0", "quiet"), ("meshopt", "quiet"),
                                        ("qecd", "quiet"), ("ours", "loaded"), ("ours-t0", "loaded")])]
        if not ms:
            continue
        om = [t(m, "ours") / t(m, "meshopt") for m in ms]
        tm = [t(m, "ours-t0") / t(m, "meshopt") for m in ms]
        oq = [t(m, "ours") / t(m, "qecd") for m in ms]
        quiet = [t(m, "ours-t0") / t(m, "ours") for m in ms]
        loaded = [t(m, "ours-t0", "loaded") / t(m, "ours", "loaded") for m in ms]
        name = "all" if rt == "all" else f"{float(rt):g}"
        out.append(
            f"| {name} | {len(ms)} | {statistics.median(om):.1f} | {quantile(om, 0.9):.1f} | {max(om):.1f} | "
            f"{statistics.median(tm):.1f} | {statistics.median(oq):.2f} | {max(oq):.2f} | "
            f"{sum(x > 1 for x in oq)} | {statistics.median(quiet):.2f} / {max(quiet):.2f} | "
            f"{statistics.median(loaded):.2f} / {max(loaded):.2f} | {sum(x > 1.05 for x in loaded)} |")
    out += ["", "*t0 ÷ one thread*: below 1, the default thread count is faster; *slower*: more than 5 % "
            "slower (the machine's noise between two runs).", "",
            "### Time per input face, by size", "",
            "| input faces | runs | ours µs | ours-t0 µs | meshopt µs | QECD µs |", "|---|---|---|---|---|---|"]
    for lo, hi in [(5000, 20000), (20000, 100000), (100000, 10 ** 12)]:
        ms = [(k, m) for k, m in runs.items() if lo <= int(next(iter(m.values()))["input_faces"]) < hi
              and ("qecd", "quiet") in m and ("meshopt", "quiet") in m]
        if not ms:
            continue
        per = lambda method: statistics.median(
            1e6 * t(m, method) / int(m[(method, "quiet")]["input_faces"]) for _, m in ms)
        label = f"{lo // 1000} k – {hi // 1000} k" if hi < 10 ** 12 else f"{lo // 1000} k and more"
        out.append(f"| {label} | {len(ms)} | {per('ours'):.1f} | {per('ours-t0'):.1f} | "
                   f"{per('meshopt'):.2f} | {per('qecd'):.1f} |")
    out += ["", "### Every run", "",
            "| mesh | faces | ratio | ours s | ours-t0 s | meshopt s | QECD s | ours ÷ meshopt | ours ÷ QECD | loaded: ours s / ours-t0 s |",
            "|---|---|---|---|---|---|---|---|---|---|"]
    for k in sorted(runs, key=lambda k: (k[0], k[1], -float(k[2]))):
        m = runs[k]
        if not all(x in m for x in [("ours", "quiet"), ("ours-t0", "quiet"), ("meshopt", "quiet"), ("qecd", "quiet")]):
            continue
        ld = (f"{t(m, 'ours', 'loaded'):.3f} / {t(m, 'ours-t0', 'loaded'):.3f}"
              if ("ours", "loaded") in m and ("ours-t0", "loaded") in m else "")
        out.append(f"| {k[0]}/{k[1]} | {m[('ours', 'quiet')]['input_faces']} | {float(k[2]):g} | "
                   f"{t(m, 'ours'):.3f} | {t(m, 'ours-t0'):.3f} | {t(m, 'meshopt'):.4f} | {t(m, 'qecd'):.3f} | "
                   f"{t(m, 'ours') / t(m, 'meshopt'):.1f} | {t(m, 'ours') / t(m, 'qecd'):.2f} | {ld} |")
    splice(dst, "\n".join(out) + "\n")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
