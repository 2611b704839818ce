"""Polygons through the command line: a quad-dominant sheet with pentagons and hexagons
(tests/support/polygon_sheet.py), as OBJ (a texture coordinate per corner) and as OFF, comes
out with every polygon the run left untouched whole and the rest plain triangles, as MeshLab's
filter, pymeshlab and the numpy API keep them:
- every output face of more than three corners is an input polygon: the same corners in the
  same cyclic order (positions and, in OBJ, texture coordinates), never a merge of pieces;
- the faces' triangles add up to the face count the run reports;
- at --ratio 1 every polygon comes back whole; at 0.5 some do, and the OBJ and OFF runs keep
  the same ones; tiled runs (--memory) keep them by the same rule.

    test_polygons.py VRSIMPLIFY SUPPORT_DIR OUT_DIR
"""
import json
import pathlib
import subprocess
import sys

vrs, support, out = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
out.mkdir(parents=True, exist_ok=True)
sys.path.insert(0, str(support))
import polygon_sheet  # noqa: E402

import numpy as np  # noqa: E402


def f32(text):
    """A coordinate as the float it stands for (what the tool reads and writes back)."""
    return float(np.float32(text))


failures = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


def read(path):
    """The faces of an OBJ or OFF file, each a tuple of corners: (position,) or (position, uv)."""
    text = path.read_text().split("\n")
    faces = []
    if path.suffix == ".obj":
        v, vt = [], []
        for line in text:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                v.append(tuple(f32(x) for x in w[1:4]))
            elif w[0] == "vt":
                vt.append(tuple(f32(x) for x in w[1:3]))
            elif w[0] == "f":
                corners = []
                for c in w[1:]:
                    i = c.split("/")
                    corners.append((v[int(i[0]) - 1], vt[int(i[1]) - 1] if len(i) > 1 and i[1] else None))
                faces.append(tuple(corners))
        return faces
    lines = [line for line in text if line.strip()]
    nv, nf = map(int, lines[1].split()[:2])
    v = [tuple(f32(x) for x in line.split()[:3]) for line in lines[2:2 + nv]]
    for line in lines[2 + nv:2 + nv + nf]:
        w = line.split()
        faces.append(tuple((v[int(i)], None) for i in w[1:1 + int(w[0])]))
    return faces


def canonical(face):
    """The face from its least corner on: one cyclic order, one tuple."""
    k = face.index(min(face))
    return face[k:] + face[:k]


def run(src, dst, *args):
    threads = [] if "--memory" in args else ["--threads", "1"]  # tiles run on one thread each
    p = subprocess.run([vrs, str(src), str(dst), "--json", *threads, *args],
                       capture_output=True, text=True)
    check(p.returncode == 0, f"{src.name} -> {dst.name} {' '.join(args)} runs ({p.stderr.strip()[:200]})")
    return json.loads(p.stdout) if p.returncode == 0 else {}


kept = {}
for ext in ("obj", "off"):
    src = out / f"sheet.{ext}"
    polygon_sheet.write(src)
    inp = read(src)
    polygons = {canonical(f) for f in inp if len(f) > 3}
    check(len(polygons) > 1000 and any(len(f) == 5 for f in polygons) and any(len(f) == 6 for f in polygons),
          f"{ext}: the sheet has {len(polygons)} polygons, pentagons and hexagons among them")
    same = out / f"same.{ext}"
    report = run(src, same, "--ratio", "1")
    back = read(same) if same.exists() else []
    check(sorted(canonical(f) for f in back) == sorted(canonical(f) for f in inp),
          f"{ext}: at --ratio 1 every polygon and triangle comes back as it was")
    half = out / f"half.{ext}"
    report = run(src, half, "--ratio", "0.5")
    faces = read(half) if half.exists() else []
    big = [canonical(f) for f in faces if len(f) > 3]
    check(report.get("target_reached") and sum(len(f) - 2 for f in faces) == report.get("output_faces"),
          f"{ext}: at 0.5 the {len(faces)} faces hold the {report.get('output_faces')} triangles reported")
    check(all(f in polygons for f in big),
          f"{ext}: every one of the {len(big)} output polygons is an input polygon, corners in order")
    check(len(big) > 20 and any(len(f) == 5 for f in big), f"{ext}: polygons left untouched stay whole")
    kept[ext] = sorted(tuple(c[0] for c in f) for f in big)
check(kept["obj"] == kept["off"], "OBJ and OFF keep the same polygons")

# Tiled runs (--memory): the same rule, by input vertex id across tiles and levels. A larger
# sheet (28 800 triangles), so that a small budget cuts it into tiles.
positions, polys = polygon_sheet.sheet(120)
for ext in ("obj", "off"):
    src = out / f"big.{ext}"
    with open(src, "w") as f:
        if ext == "obj":
            for x, y, z in positions:
                f.write("v %.6f %.6f %.6f\nvt %.6f %.6f\n" % (x, y, z, x, y))
            for p in polys:
                f.write("f %s\n" % " ".join("%d/%d" % (v + 1, v + 1) for v in p))
        else:
            f.write("OFF\n%d %d 0\n" % (len(positions), len(polys)))
            f.writelines("%.6f %.6f %.6f\n" % q for q in positions)
            f.writelines("%d %s\n" % (len(p), " ".join(map(str, p))) for p in polys)
    polygons = {canonical(f) for f in read(src) if len(f) > 3}
    report = run(src, out / f"big-tiled.{ext}", "--ratio", "0.5", "--memory", "1M")
    faces = read(out / f"big-tiled.{ext}") if (out / f"big-tiled.{ext}").exists() else []
    big = [canonical(f) for f in faces if len(f) > 3]
    check(report.get("tiled") and sum(len(f) - 2 for f in faces) == report.get("output_faces"),
          f"{ext}, tiled: the {len(faces)} faces hold the {report.get('output_faces')} triangles reported")
    check(len(big) > 100 and all(f in polygons for f in big) and any(len(f) == 6 for f in big),
          f"{ext}, tiled: {len(big)} polygons whole, every one an input polygon, corners in order")

# Turned: a sheet written with every face reversed keeps its polygons reversed, whole.
flipped = out / "flipped.off"
positions, polys = polygon_sheet.sheet()
flipped.write_text(f"OFF\n{len(positions)} {len(polys)} 0\n" +
                   "".join("%.6f %.6f %.6f\n" % p for p in positions) +
                   "".join("%d %s\n" % (len(p), " ".join(map(str, reversed(p)))) for p in polys))
reversed_polygons = {canonical(f) for f in read(flipped) if len(f) > 3}
run(flipped, out / "flipped-half.off", "--ratio", "0.5")
big = [canonical(f) for f in read(out / "flipped-half.off") if len(f) > 3]
check(len(big) > 20 and all(f in reversed_polygons for f in big),
      f"a reversed sheet: its {len(big)} output polygons are its own, reversed as it wrote them")

# One pentagon written the other way from its neighbours: the run turns it as the surface
# (report's reoriented faces), and writes it whole, turned.
one = out / "one-turned.off"
k = next(i for i, p in enumerate(polys) if len(p) == 5)
one.write_text(f"OFF\n{len(positions)} {len(polys)} 0\n" +
               "".join("%.6f %.6f %.6f\n" % p for p in positions) +
               "".join("%d %s\n" % (len(p), " ".join(map(str, reversed(p) if i == k else p)))
                       for i, p in enumerate(polys)))
report = run(one, out / "one-turned-same.off", "--ratio", "1")
faces = {canonical(f) for f in read(out / "one-turned-same.off")}
check(report.get("input_issues", {}).get("reoriented_faces") == 3 and
      canonical(tuple(read(out / "sheet.off")[k])) in faces,
      "a pentagon written against its neighbours comes out whole, turned as the surface")

sys.exit(1 if failures else 0)
