#!/usr/bin/env python3
"""bench/speed_corpus_report.py: the ratios of two meshes worked by hand, and the section put in
SPEED.md after its title, in place of the one before, the rest of the report kept."""
import csv
import os
import subprocess
import sys
import tempfile

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
REPORT = os.path.join(TOP, "bench", "speed_corpus_report.py")
HEADER = ["set", "mesh", "input_faces", "ratio", "target_faces", "method", "load", "output_faces",
          "seconds", "error_mean"]


def rows(mesh, faces, ours, t0, meshopt, qecd, loaded_ours, loaded_t0):
    out = []
    for method, load, s in [("ours", "quiet", ours), ("ours-t0", "quiet", t0), ("meshopt", "quiet", meshopt),
                            ("qecd", "quiet", qecd), ("ours", "loaded", loaded_ours),
                            ("ours-t0", "loaded", loaded_t0)]:
        out.append(["cgal", mesh, faces, "0.1", faces // 10, method, load, faces // 10, s, 1e-4])
    return out


def main():
    with tempfile.TemporaryDirectory() as tmp:
        src, speed = os.path.join(tmp, "c.csv"), os.path.join(tmp, "SPEED.md")
        with open(src, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(HEADER)
            # ours ÷ meshopt 10 and 30 (median 20); ours ÷ QECD 2 and 0.5 (one slower);
            # loaded t0 ÷ one thread 1.2 (slower) and 0.5.
            w.writerows(rows("a", 10000, 1.0, 0.6, 0.1, 0.5, 1.0, 1.2))
            w.writerows(rows("b", 50000, 3.0, 1.8, 0.1, 6.0, 2.0, 1.0))
        open(speed, "w").write("# Speed and memory\n\n## The bunny\n\nkept\n")
        for _ in range(2):  # the second run replaces the section, never adds one
            subprocess.run([sys.executable, REPORT, src, speed], check=True)
        text = open(speed).read()
        assert text.count("## Real meshes") == 1, text
        assert text.startswith("# Speed and memory\n\n<!-- real meshes"), text[:80]
        assert text.rstrip().endswith("## The bunny\n\nkept"), text[-80:]
        row = next(l for l in text.splitlines() if l.startswith("| 0.1 |"))
        cells = [c.strip() for c in row.strip("|").split("|")]
        # ratio, runs, ours÷meshopt median, p90, worst, t0÷meshopt median, ours÷QECD median, worst,
        # slower than QECD, quiet t0÷one, loaded t0÷one, loaded runs t0 slower
        assert cells[:9] == ["0.1", "2", "20.0", "28.0", "30.0", "12.0", "1.25", "2.00", "1"], cells
        assert cells[10] == "0.85 / 1.20" and cells[11] == "1", cells
    print("speed_corpus_report: ratios as computed by hand, the section spliced once")


if __name__ == "__main__":
    main()
