#!/usr/bin/env python3
"""bench/speed_report.py's sections from the run's own figures: the serial part's projection and
the machine's ceiling for two threads (medians of the repeats, the pair's runs pooled)."""
import csv
import os
import subprocess
import sys
import tempfile

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
REPORT = os.path.join(TOP, "bench", "speed_report.py")


def write(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)


def row_of(text, mesh, heading):
    section = text.split(heading, 1)[1]
    return next(line for line in section.splitlines() if line.startswith(f"| {mesh} |"))


def main():
    with tempfile.TemporaryDirectory() as d:
        speed, serial, ceiling, out = (os.path.join(d, n) for n in
                                       ("speed.csv", "serial.csv", "ceiling.csv", "SPEED.md"))
        write(speed, ["mesh", "input_faces", "method", "seconds", "peak_mb"],
              [["m", 1000, "ours", 4.0, 10], ["m", 1000, "ours-t2", 2.2, 11],
               ["m", 1000, "meshopt", 1.0, 12]])
        # m: Amdahl's 14.3x on 16 cores (s = 0.008) but 9.6x by its loops' chunks: judged by
        # the chunks, missed; o: an older CSV without them, judged by Amdahl.
        write(serial, ["mesh", "seconds", "parallel_seconds", "serial_fraction", "by_chunks_8",
                       "by_chunks_16"],
              [["m", 4.0, 3.968, 0.008, 6.5, 9.6], ["p", 4.0, 3.99, 0.0025, 7.8, 15.0]])
        serial_old = os.path.join(d, "serial_old.csv")
        write(serial_old, ["mesh", "seconds", "parallel_seconds", "serial_fraction"],
              [["o", 4.0, 3.9, 0.025]])
        # Medians: alone 4.0, each of the pair 4.3 (of all six: 4.0 4.2 4.2 4.4 4.6 5.0), two
        # threads 2.2: ceiling 2 x 4.0 / 4.3 = 1.86x, scaling 4.0 / 2.2 = 1.82x, 98 % of it.
        write(ceiling, ["mesh", "alone", "pair_a", "pair_b", "two_threads"],
              [["m", 4.0, 4.0, 4.4, 2.2], ["m", 3.0, 4.2, 5.0, 2.0], ["m", 5.0, 4.6, 4.2, 2.4],
               ["n", 4.0, 4.0, 4.0, 2.0]])
        subprocess.run([sys.executable, REPORT, speed, out, serial, ceiling], check=True)
        text = open(out).read()
        # 16 cores by Amdahl from s = 0.008: 1 / (0.008 + 0.992 / 16) = 14.3x; by chunks 9.6x.
        s = row_of(text, "m", "## Serial part")
        assert "| 0.008 | 7.6× / 14.3× | 6.5× / 9.6× | ≥ 12× | **missed** |" in s, s
        p = row_of(text, "p", "## Serial part")
        assert p.endswith("| 7.8× / 15.0× | ≥ 12× | met |"), p
        subprocess.run([sys.executable, REPORT, speed, out, serial_old, ceiling], check=True)
        # Without the chunks, Amdahl from s = 0.025: 1 / (0.025 + 0.975 / 16) = 11.6x, missed.
        o = row_of(open(out).read(), "o", "## Serial part")
        assert "| 0.025 | 6.8× / 11.6× | — | ≥ 12× | **missed** |" in o, o
        m = row_of(text, "m", "## What two threads can get")
        cells = [c.strip() for c in m.strip("|").split("|")]
        assert cells == ["m", "3", "4.00", "4.30", "2.20", "1.86×", "1.82×", "98 %", "**missed**"], cells
        n = row_of(text, "n", "## What two threads can get")
        assert "| 2.00× | 2.00× | 100 % | met |" in n, n
    print("speed_report: serial and ceiling sections as computed by hand")


if __name__ == "__main__":
    main()
