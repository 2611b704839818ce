#!/usr/bin/env python3
"""The worst runs of ours, rendered beside MeshLab's QECD: users meet their own mesh, not a median.

usage: render_worst.py QUALITY_CSV OUT_DIR VRS_BENCH VRS_RENDER ON_DISPLAY [N]

Takes the N runs (default 10) of "ours" with the highest mean-error ratio to QECD at equal size
(as quality_report.py computes it: QECD run to the faces ours kept where ours stopped short),
runs both again on the same mesh and target (`vrs_bench --save`), renders the input, ours and
QECD's output at the same size from one view, and writes OUT_DIR/NN-set-mesh-ratio.png (three
panels: input | ours | QECD) and OUT_DIR/worst.md, which quality_report.py includes.
The mesh files are found by name in the data set's list (scripts/lib/bench_meshes.sh --cad).
"""
import csv
import os
import subprocess
import sys
import tempfile
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import quality_report as q  # noqa: E402

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def mesh_paths():
    listing = subprocess.run([os.path.join(TOP, "scripts/lib/bench_meshes.sh"), "--cad"],
                             check=True, capture_output=True, text=True).stdout.split()
    out = {}
    for path in listing:
        name = os.path.splitext(os.path.basename(path))[0]
        s = "assimp" if path.startswith("/usr/share/assimp/") else "cad" if "/cad-parts-" in path else "cgal"
        out.setdefault((s, name), path)
        # bench_quality.sh names one model in several formats NAME-EXT (Wuson-off, Wuson-stl).
        out.setdefault((s, f"{name}-{os.path.splitext(path)[1][1:]}"), path)
    return out


def main():
    csv_path, out_dir, bench, render, on_display = sys.argv[1:6]
    n = int(sys.argv[6]) if len(sys.argv) > 6 else 10
    runs = defaultdict(dict)
    for row in csv.DictReader(open(csv_path)):
        if row["output_faces"]:
            runs[(row["set"], row["mesh"], row["ratio"])][row["method"]] = row
    worst = sorted(q.ratios(runs, list(runs), "ours", "error_mean"), key=lambda t: -t[0])[:n]
    paths = mesh_paths()
    os.makedirs(out_dir, exist_ok=True)
    for f in os.listdir(out_dir):
        if f.endswith(".png"):
            os.remove(f"{out_dir}/{f}")
    lines = []
    with tempfile.TemporaryDirectory() as tmp:
        for i, (x, key) in enumerate(worst, 1):
            s, mesh, rt = key
            path = paths.get((s, mesh))
            if path is None:
                continue
            r, qe = runs[key]["ours"], q.reference(runs[key], "ours", q.EQUAL)
            reference = qe["method"]  # qecd, or qecd-at-ours where ours stopped short
            subprocess.run([bench, path, "--name", "m", "--ratios", rt, "--methods", f"ours,{reference}",
                            "--save", tmp], check=True, capture_output=True)
            panels = []
            for label, src in [("input", path), ("ours", f"{tmp}/m_{rt}_ours.ply"),
                               ("qecd", f"{tmp}/m_{rt}_{reference}.ply")]:
                png = f"{tmp}/{label}.png"
                subprocess.run([on_display, "-s", "-screen 0 1024x768x24", render, src, png,
                                "--size", "360", "360", "--azimuth", "30", "--elevation", "25"],
                               check=True, capture_output=True)
                panels.append(png)
            name = f"{i:02d}-{s}-{mesh}-{float(rt):g}.png".replace("^", "").replace("+", "")
            subprocess.run(["convert", *panels, "+append", f"{out_dir}/{name}"], check=True)
            lines.append(f"{i}. **{s}/{mesh} at {float(rt):g}**: mean error {x:.2f}× QECD's at "
                         f"{qe['output_faces']} faces ({float(r['error_mean']):.3g} against "
                         f"{float(qe['error_mean']):.3g} of the diagonal), ours {r['output_faces']} "
                         f"faces for {r['target_faces']}"
                         f"{', stopped: ' + r['note'].split(':')[0] if r['note'] else ''}. "
                         f"Input, ours, QECD at the same size:\n\n   ![{mesh}](renders/worst/{name})\n")
    open(f"{out_dir}/worst.md", "w").write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
