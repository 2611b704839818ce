#!/usr/bin/env python3
"""The numpy API's cost over the core, and the GIL released during a run.

usage: python_api.py VRSIMPLIFY_CLI MESH.ply [REPEATS]

Overhead: vrsimplify.simplify (arrays in, arrays and maps out) against the core's own time for
the same mesh and target as the CLI reports it (`seconds_simplify`: vrs::simplify alone), one
thread and the default threads, alternated, medians. GIL: two Python threads simplifying two
copies at once, one core thread each, against the two one after the other.
"""
import json
import statistics
import subprocess
import sys
import tempfile
import threading
import time

import vrsimplify
from python_peers import read_ply


def core_seconds(cli, mesh, threads):
    with tempfile.TemporaryDirectory() as d:
        out = subprocess.run([cli, mesh, f"{d}/out.ply", "--ratio", "0.1", "--threads",
                              str(threads), "--json", "--quiet"],
                             capture_output=True, text=True, check=True)
    return json.loads(out.stdout)["seconds_simplify"]


def api_seconds(v, f, threads):
    t0 = time.perf_counter()
    vrsimplify.simplify(v, f, ratio=0.1, threads=threads)
    return time.perf_counter() - t0


def main():
    cli, mesh = sys.argv[1], sys.argv[2]
    repeats = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    v, f = read_ply(mesh)
    print(f"{mesh}: {len(f)} faces, target 10 %")
    print("| threads | core (CLI's seconds_simplify) | numpy API | overhead |")
    print("|---|---|---|---|")
    for threads in (1, 0):
        core, api = [], []
        for _ in range(repeats):
            core.append(core_seconds(cli, mesh, threads))
            api.append(api_seconds(v, f, threads))
        c, a = statistics.median(core), statistics.median(api)
        print(f"| {threads or 'all'} | {c:.3f} s | {a:.3f} s | {100 * (a / c - 1):+.1f} % |")
    parts = [(v, f), (v, f.copy())]
    serial, together = [], []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for p in parts:
            vrsimplify.simplify(*p, ratio=0.1, threads=1)
        serial.append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        ts = [threading.Thread(target=vrsimplify.simplify, args=p,
                               kwargs=dict(ratio=0.1, threads=1)) for p in parts]
        for t in ts:
            t.start()
        for t in ts:
            t.join()
        together.append(time.perf_counter() - t0)
    s, t = statistics.median(serial), statistics.median(together)
    print(f"\nTwo Python threads, the mesh each, one core thread each: one after the other "
          f"{s:.3f} s, at once {t:.3f} s (×{s / t:.2f})")


if __name__ == "__main__":
    main()
