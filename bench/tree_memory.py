#!/usr/bin/env python3
"""Runs a command and prints the peak of the summed resident memory of it and every process it
starts (sampled every 50 ms from /proc), then the command's wall time: what a tiled run with
worker processes really holds at once, which no single process's peak shows.

usage: tree_memory.py [--disk DIR] COMMAND [ARG...]  -> last line: "peak_tree_mb SECONDS EXIT"
  --disk DIR: also the largest total size of the files under DIR (sampled every second),
  in MB, written to DIR.peak (a tiled run's work directory: the disk it needs).
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


def tree_bytes(top):
    total = 0
    for root, _, files in os.walk(top):
        for name in files:
            try:
                total += os.stat(os.path.join(root, name)).st_size
            except OSError:
                continue  # removed meanwhile
    return total


def main():
    args = sys.argv[1:]
    disk = None
    if args[:1] == ["--disk"]:
        disk, args = args[1], args[2:]
    t0 = time.perf_counter()
    p = subprocess.Popen(args, start_new_session=True)
    peak = disk_peak = 0
    last_walk = 0.0
    while p.poll() is None:
        peak = max(peak, session_rss(p.pid))
        if disk and time.perf_counter() - last_walk >= 1.0:
            disk_peak = max(disk_peak, tree_bytes(disk))
            last_walk = time.perf_counter()
        time.sleep(0.05)
    if disk:
        with open(disk.rstrip("/") + ".peak", "w") as f:
            f.write(f"{disk_peak / 2**20:.0f}\n")
    print(f"{peak / 2**20:.0f} {time.perf_counter() - t0:.2f} {p.returncode}")


if __name__ == "__main__":
    main()
