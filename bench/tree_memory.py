#!/usr/bin/env python3
"""Runs a command and prints the peak of the summed resident memory of it and every process it
starts (sampled every 50 ms from /proc), then the command's wall time: what a tiled run with
worker processes really holds at once, which no single process's peak shows.

usage: tree_memory.py COMMAND [ARG...]     -> last line: "peak_tree_mb SECONDS EXIT"
"""
import os
import subprocess
import sys
import time

PAGE = os.sysconf("SC_PAGE_SIZE")


def session_rss(sid):
    total = 0
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open(f"/proc/{pid}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
            if int(fields[3]) != sid:  # field 6 of stat: the session id
                continue
            with open(f"/proc/{pid}/statm") as f:
                total += int(f.read().split()[1]) * PAGE
        except (OSError, IndexError, ValueError):
            continue  # the process ended meanwhile
    return total


def main():
    t0 = time.perf_counter()
    p = subprocess.Popen(sys.argv[1:], start_new_session=True)
    peak = 0
    while p.poll() is None:
        peak = max(peak, session_rss(p.pid))
        time.sleep(0.05)
    print(f"{peak / 2**20:.0f} {time.perf_counter() - t0:.2f} {p.returncode}")


if __name__ == "__main__":
    main()
