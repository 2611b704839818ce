"""Readers agree: one mesh — with a NaN vertex, a duplicate face, a degenerate face (a repeated
index) and an unused vertex — written as ascii and binary PLY, OBJ, OFF and ascii and binary STL,
gives the same run through the CLI: the same counts of input faces, of NaN vertices, of dropped
degenerate faces, the same output face count and stop reason (STL, a soup of triangles, is
welded by position; its unused vertex does not exist). The welded soup numbers its vertices in
another order, and equal prices are taken in vertex order: its last removal may take one face
more or less than the indexed formats' (a border vertex's removal takes one face, an interior
one's two), so the two STL runs agree with each other exactly and with the rest within a face.

    test_readers_agree.py VRSIMPLIFY OUT_DIR
"""
import json
import pathlib
import struct
import subprocess
import sys

import numpy as np

vrs, out = sys.argv[1], pathlib.Path(sys.argv[2])
out.mkdir(parents=True, exist_ok=True)

# A bumpy grid (open, 2 * 30 * 30 faces), then the hostile parts.
n = 30
i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1), indexing="ij")
v = np.stack([i.ravel() / n, j.ravel() / n, 0.05 * np.sin(7 * i.ravel() / n) * np.cos(5 * j.ravel() / n)], 1)
idx = (i * (n + 1) + j)[:-1, :-1].ravel()
f = np.concatenate([np.stack([idx, idx + n + 1, idx + 1], 1), np.stack([idx + 1, idx + n + 1, idx + n + 2], 1)])
v = np.vstack([v, [[np.nan, 0.5, 0.5]], [[2.0, 2.0, 2.0]]])  # a NaN vertex (with a face), an unused one
nan = len(v) - 2
f = np.vstack([f, f[:1], [[0, 0, 1]], [[nan, 0, 1]]])  # a duplicate, a degenerate, one on the NaN


def fmt(x):
    return "nan" if np.isnan(x) else "%.9g" % x


files = {}
p = out / "m-ascii.ply"
p.write_text(f"ply\nformat ascii 1.0\nelement vertex {len(v)}\nproperty float x\nproperty float y\nproperty float z\n"
             f"element face {len(f)}\nproperty list uchar int vertex_indices\nend_header\n"
             + "".join(" ".join(fmt(c) for c in r) + "\n" for r in v)
             + "".join(f"3 {a} {b} {c}\n" for a, b, c in f))
files["ascii PLY"] = p
p = out / "m-binary.ply"
rec = np.zeros(len(f), [("n", "u1"), ("v", "<i4", (3,))])
rec["n"], rec["v"] = 3, f
p.write_bytes(f"ply\nformat binary_little_endian 1.0\nelement vertex {len(v)}\nproperty float x\nproperty float y\n"
              f"property float z\nelement face {len(f)}\nproperty list uchar int vertex_indices\nend_header\n".encode()
              + v.astype("<f4").tobytes() + rec.tobytes())
files["binary PLY"] = p
p = out / "m.obj"
p.write_text("".join("v " + " ".join(fmt(c) for c in r) + "\n" for r in v)
             + "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in f))
files["OBJ"] = p
p = out / "m.off"
p.write_text(f"OFF\n{len(v)} {len(f)} 0\n" + "".join(" ".join(fmt(c) for c in r) + "\n" for r in v)
             + "".join(f"3 {a} {b} {c}\n" for a, b, c in f))
files["OFF"] = p
p = out / "m-ascii.stl"
tri = v.astype(np.float32)[f]
p.write_text("solid m\n" + "".join("facet normal 0 0 0\nouter loop\n" + "".join(
    "vertex " + " ".join(fmt(c) for c in corner) + "\n" for corner in t) + "endloop\nendfacet\n" for t in tri)
    + "endsolid m\n")
files["ascii STL"] = p
p = out / "m-binary.stl"
p.write_bytes(b"\0" * 80 + struct.pack("<I", len(f)) + b"".join(
    struct.pack("<12fH", 0, 0, 0, *t.ravel(), 0) for t in tri))
files["binary STL"] = p

keys = ("input_faces", "output_faces", "stop_reason")
issues = ("degenerate_faces", "nonfinite_vertices", "reoriented_faces")
runs = {}
for label, path in files.items():
    r = subprocess.run([vrs, str(path), str(out / ("o-" + path.name)), "--ratio", "0.2", "--json"],
                       capture_output=True, text=True)
    if r.returncode != 0:
        runs[label] = {"error": r.stderr.strip()}
        continue
    report = json.loads(r.stdout)
    runs[label] = {k: report.get(k) for k in keys}
    runs[label].update({k: report.get("input_issues", {}).get(k, 0) for k in issues})
for label, got in runs.items():
    print(f"{label:11s} {got}")
def agree(got, ref):
    if got == ref:
        return True
    if "error" in got or "error" in ref:
        return False
    return all(got[k] == ref[k] for k in got if k != "output_faces") and abs(got["output_faces"] - ref["output_faces"]) <= 1


reference, soup = runs["binary PLY"], runs["binary STL"]
bad = [label for label, got in runs.items() if not (got == soup if "STL" in label else got == reference)]
bad += [] if agree(soup, reference) else ["STL against the indexed formats"]
print("readers agree" if not bad else f"readers disagree: {bad}")
sys.exit(1 if bad else 0)
