"""Untouched means untouched: every output vertex is an input vertex, bit for bit, whatever
the precision and the encoding. A georeferenced terrain with double coordinates (x ~ 500 000,
y ~ 4 100 000 m: a float would step by 0.25-0.5 m), colors and a quality, written as binary
little- and big-endian and ascii PLY (17 digits), and a float ascii PLY (9 digits), through the
CLI in core (binary and --ascii output) and tiled (--memory): each output vertex's values, as
their declared types, are one input vertex's; the target is reached in core (the core sees the
doubles, not float-rounded ones). The same terrain as OBJ and OFF with 17 digits, and the
double PLY written as OBJ and OFF: every output coordinate triple, read as doubles, is an input
vertex's (an OBJ's v line is the input's, as written). STL (float) says so.

    test_exact_coordinates.py VRSIMPLIFY OUT_DIR
"""
import pathlib
import subprocess
import sys

import numpy as np

vrs, out = sys.argv[1], pathlib.Path(sys.argv[2])
out.mkdir(parents=True, exist_ok=True)
TYPES = {"double": "f8", "float": "f4", "uchar": "u1", "int": "i4", "uint": "u4"}


def terrain(n=120):
    rng = np.random.default_rng(7)
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    x = 500000.123456789 + 0.5 * i.ravel() + 1e-7 * rng.random(n * n)
    y = 4100000.987654321 + 0.5 * j.ravel() + 1e-7 * rng.random(n * n)
    z = 120.0 + np.sin(i.ravel() / 9.0) * np.cos(j.ravel() / 7.0) * 3 + 0.01 * rng.random(n * n)
    q = np.arange(n * n) % 97
    idx = (i * n + j)[:-1, :-1].ravel()
    faces = np.concatenate([np.stack([idx, idx + n, idx + 1], 1), np.stack([idx + 1, idx + n, idx + n + 1], 1)])
    return x, y, z, q, faces


def write(path, fmt, props, columns, faces):
    """props: [(type, name)]; columns: arrays; fmt: ascii / binary_little_endian / binary_big_endian."""
    nv = len(columns[0])
    head = f"ply\nformat {fmt} 1.0\nelement vertex {nv}\n" + "".join(f"property {t} {n}\n" for t, n in props)
    head += f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n"
    with open(path, "wb") as f:
        f.write(head.encode())
        if fmt == "ascii":
            digits = {"double": "%.17g", "float": "%.9g"}
            for row in zip(*columns):
                f.write((" ".join(digits.get(t, "%d") % v for (t, _), v in zip(props, row)) + "\n").encode())
            for a, b, c in faces:
                f.write(f"3 {a} {b} {c}\n".encode())
        else:
            e = ">" if "big" in fmt else "<"
            rec = np.zeros(nv, [(n, e + TYPES[t]) for t, n in props])
            for (t, n), col in zip(props, columns):
                rec[n] = col
            f.write(rec.tobytes())
            fr = np.zeros(len(faces), [("n", "u1"), ("v", e + "i4", (3,))])
            fr["n"], fr["v"] = 3, faces
            f.write(fr.tobytes())


def read_vertices(path):
    """The vertex element as a structured array of its declared types (native order)."""
    data = path.read_bytes()
    end = data.index(b"end_header\n") + 11
    header = data[:end].decode().splitlines()
    fmt = next(l.split()[1] for l in header if l.startswith("format"))
    nv = int(next(l.split()[2] for l in header if l.startswith("element vertex")))
    props, element = [], None
    for l in header:
        w = l.split()
        if w[0] == "element":
            element = w[1]
        elif w[0] == "property" and element == "vertex":
            props.append((w[2], TYPES[w[1]]))
    if fmt == "ascii":
        rows = data[end:].decode().splitlines()[:nv]
        rec = np.zeros(nv, [(n, t) for n, t in props])
        for k, (n, t) in enumerate(props):
            rec[n] = [np.array(r.split()[k]).astype(t) if t[0] == "f" else int(r.split()[k]) for r in rows]
        return rec, props
    e = ">" if "big" in fmt else "<"
    rec = np.frombuffer(data, [(n, e + t) for n, t in props], nv, end)
    return rec.astype([(n, t) for n, t in props]), props


failed = []


def check(name, cond, what):
    print(("ok   " if cond else "FAIL ") + f"{name}: {what}")
    if not cond:
        failed.append(name)


x, y, z, q, faces = terrain()
props = [("double", "x"), ("double", "y"), ("double", "z"), ("uchar", "red"), ("uchar", "green"),
         ("uchar", "blue"), ("float", "quality")]
cols = [x, y, z, q * 2 % 256, q * 3 % 256, q * 5 % 256, q / 8.0]
inputs = {}
for fmt in ("binary_little_endian", "binary_big_endian", "ascii"):
    p = out / f"terrain-{fmt}.ply"
    write(p, fmt, props, cols, faces)
    inputs[fmt] = p
floats = out / "float-ascii.ply"  # float coordinates written with 9 digits
write(floats, "ascii", [("float", "x"), ("float", "y"), ("float", "z")],
      [np.float32(x - 500000), np.float32(y - 4100000), np.float32(z)], faces)
inputs["float ascii"] = floats

for label, src in inputs.items():
    ref, ref_props = read_vertices(src)
    rows = {r.tobytes() for r in ref}
    runs = [("in core, binary", [], ".ply"), ("in core, --ascii", ["--ascii"], ".ply"),
            ("tiled", ["--memory", "1M"], ".ply")]
    for run, args, ext in runs:
        dst = out / f"{src.stem}-{run.replace(' ', '').replace(',', '-')}{ext}"
        r = subprocess.run([vrs, str(src), str(dst), "--ratio", "0.1", "--json", *args],
                           capture_output=True, text=True)
        if r.returncode != 0:
            check(f"{label} / {run}", False, r.stderr.strip())
            continue
        got, got_props = read_vertices(dst)
        same_layout = got_props == ref_props
        exact = same_layout and all(g.tobytes() in rows for g in got)
        check(f"{label} / {run}", exact,
              f"{len(got)} output vertices, every one an input vertex in every property"
              if exact else f"layout {got_props} vs {ref_props}")
        if run.startswith("in core"):
            check(f"{label} / {run} target", '"target_reached":true' in r.stdout, "the target reached")
# Text formats: 17 digits in, the same coordinates out (and from the double PLY).
xyz = {(a, b, c) for a, b, c in zip(x.tolist(), y.tolist(), z.tolist())}
(out / "terrain.obj").write_text("".join(f"v {a!r} {b!r} {c!r}\n" for a, b, c in zip(x.tolist(), y.tolist(), z.tolist()))
                                 + "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in faces))
(out / "terrain.off").write_text(f"OFF\n{len(x)} {len(faces)} 0\n"
                                 + "".join(f"{a!r} {b!r} {c!r}\n" for a, b, c in zip(x.tolist(), y.tolist(), z.tolist()))
                                 + "".join(f"3 {a} {b} {c}\n" for a, b, c in faces))
obj_lines = set((out / "terrain.obj").read_text().splitlines())


def text_vertices(path):
    lines = [l for l in path.read_text().splitlines() if l.strip()]
    if path.suffix == ".obj":
        return [l for l in lines if l.startswith("v ")]
    words = lines[1].split() if len(lines[0].split()) == 1 else lines[0].split()[1:]
    start = 2 if len(lines[0].split()) == 1 else 1
    return lines[start:start + int(words[0])]


for src in (out / "terrain.obj", out / "terrain.off", inputs["binary_little_endian"], inputs["ascii"]):
    for ext in (".obj", ".off"):
        dst = out / f"text-{src.stem}{ext}"
        r = subprocess.run([vrs, str(src), str(dst), "--ratio", "0.1", "--json"], capture_output=True, text=True)
        if r.returncode != 0:
            check(f"{src.name} to {ext}", False, r.stderr.strip())
            continue
        rows = text_vertices(dst)
        coords = [tuple(float(w) for w in (l.split()[1:4] if ext == ".obj" else l.split()[:3])) for l in rows]
        exact = bool(rows) and all(c in xyz for c in coords)
        if src.suffix == ".obj" and ext == ".obj":
            exact = exact and all(l in obj_lines for l in rows)  # the input's own lines
        check(f"{src.name} to {ext}", exact and '"target_reached":true' in r.stdout,
              f"{len(rows)} vertices, every coordinate an input's, the target reached")
# A format that cannot hold them says so.
r = subprocess.run([vrs, str(inputs["ascii"]), str(out / "t.stl"), "--ratio", "0.1"],
                   capture_output=True, text=True)
check("double input to .stl", r.returncode == 0 and "float cannot hold" in r.stderr, r.stderr.strip())
# The check can fail: one changed bit in one output vertex is found.
bad, _ = read_vertices(out / "terrain-binary_little_endian-incore-binary.ply")
bad = bad.copy()
bad["x"][0] = np.nextafter(bad["x"][0], np.inf)
ref, _ = read_vertices(inputs["binary_little_endian"])
check("the check sees one bit", bad[0].tobytes() not in {r.tobytes() for r in ref}, "a changed bit is caught")
print(f"{len(failed)} failed")
sys.exit(1 if failed else 0)
