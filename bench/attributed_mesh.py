#!/usr/bin/env python3
"""Large meshes with the attributes scans and photogrammetry carry, and the check that a
simplified one kept them exactly (for the tiled runs' benchmark, scripts/bench_tiled_attributes.sh).

    attributed_mesh.py textured IN.ply OUT.ply   # per-corner texcoord lists, 8 UV charts
    attributed_mesh.py colored IN.ply OUT.ply    # double coordinates (georeferenced), colors, quality
    attributed_mesh.py check INPUT OUTPUT        # prints "corners_or_vertices wrong"; exit 1 if any
    attributed_mesh.py local IN.ply OUT.ply      # positions only, float, double ones moved by the
                                                 # offset colored adds (to measure their error)

IN is a binary PLY of float x y z and uchar/int triangles (vrs_bench --loop writes them).
Textured: a corner's (u, v) is its vertex's (x, y) scaled into [0, 1], plus 2 * chart in u,
the charts cut by three planes: seams lie between charts. Colored: x and y offset to UTM-like
magnitudes (500 000, 4 100 000 m) in double, which a float cannot hold; a color and a quality
per vertex. The check matches vertices by their bytes: every output vertex record is an input
vertex record; with texcoords, every output corner's (vertex, u, v) is an input corner's.
"""
import sys

import numpy as np


def read_ply(path):
    """Header lines, vertex records (raw, one row each) and faces (and texcoords if any)."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + 11
    header = data[:end].decode().splitlines()
    assert "format binary_little_endian 1.0" in header, path
    nv = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    nf = int(next(l for l in header if l.startswith("element face")).split()[2])
    sizes = {"float": 4, "double": 8, "uchar": 1, "int": 4}
    vprops, fprops, element = [], [], None
    for line in header:
        w = line.split()
        if w[0] == "element":
            element = w[1]
        elif w[0] == "property":
            (vprops if element == "vertex" else fprops).append(w)
    vsize = sum(sizes[p[1]] for p in vprops)
    vertices = np.frombuffer(data, np.dtype((np.void, vsize)), nv, end)
    texcoord = any(p[-1] == "texcoord" for p in fprops)
    fdt = [("n", "u1"), ("v", "<i4", (3,))] + ([("m", "u1"), ("uv", "<f4", (6,))] if texcoord else [])
    faces = np.frombuffer(data, np.dtype(fdt), nf, end + vsize * nv)
    assert (faces["n"] == 3).all()
    return header, vertices, faces, texcoord


def write_ply(path, vertex_props, vertices, faces, uv=None):
    with open(path, "wb") as out:
        out.write(b"ply\nformat binary_little_endian 1.0\n")
        out.write(f"element vertex {len(vertices)}\n".encode())
        for p in vertex_props:
            out.write(f"property {p}\n".encode())
        out.write(f"element face {len(faces)}\nproperty list uchar int vertex_indices\n".encode())
        if uv is not None:
            out.write(b"property list uchar float texcoord\n")
        out.write(b"end_header\n")
        out.write(vertices.tobytes())
        fdt = [("n", "u1"), ("v", "<i4", (3,))] + ([("m", "u1"), ("uv", "<f4", (6,))] if uv is not None else [])
        rec = np.zeros(len(faces), np.dtype(fdt))
        rec["n"], rec["v"] = 3, faces
        if uv is not None:
            rec["m"], rec["uv"] = 6, uv
        out.write(rec.tobytes())


def positions(path):
    _, vertices, faces, _ = read_ply(path)
    v = np.frombuffer(vertices.tobytes(), "<f4").reshape(len(vertices), -1)[:, :3]
    return v.astype(np.float64), faces["v"].astype(np.int64)


ORIGIN = np.array([500000.123456789, 4100000.987654321, 120.0])


def textured(src, dst):
    v, f = positions(src)
    lo, hi = v.min(0), v.max(0)
    centroid = v[f].mean(1)
    rng = np.random.default_rng(3)
    chart = np.zeros(len(f), np.int64)
    for p in range(3):
        point = lo + (hi - lo) * (0.35 + 0.15 * p)
        chart |= (((centroid - point) @ rng.normal(size=3)) > 0).astype(np.int64) << p
    uv = (v[f][:, :, :2] - lo[:2]) / (hi - lo)[:2]
    uv[:, :, 0] += 2 * chart[:, None]
    write_ply(dst, ["float x", "float y", "float z"], v.astype("<f4"), f, uv.reshape(-1, 6).astype("<f4"))
    print(f"{dst}: {len(v)} vertices, {len(f)} faces, {len(np.unique(chart))} UV charts")


def colored(src, dst):
    v, f = positions(src)
    lo, hi = v.min(0), v.max(0)
    dt = np.dtype([("x", "<f8"), ("y", "<f8"), ("z", "<f8"), ("r", "u1"), ("g", "u1"), ("b", "u1"),
                   ("q", "<f4")])
    rec = np.zeros(len(v), dt)
    scale = 100.0 / (hi - lo).max()  # a 100 m object at survey coordinates
    rec["x"] = ORIGIN[0] + v[:, 0] * scale
    rec["y"] = ORIGIN[1] + v[:, 1] * scale
    rec["z"] = ORIGIN[2] + v[:, 2] * scale
    t = (v - lo) / (hi - lo)
    rec["r"], rec["g"], rec["b"] = (255 * t[:, 0]).astype("u1"), (255 * t[:, 1]).astype("u1"), (255 * t[:, 2]).astype("u1")
    rec["q"] = np.arange(len(v), dtype="<f4")
    write_ply(dst, ["double x", "double y", "double z", "uchar red", "uchar green", "uchar blue",
                    "float quality"], rec, f)
    print(f"{dst}: {len(v)} vertices, {len(f)} faces, double coordinates, colors, quality")


def check(src, dst):
    hin, vin, fin, tex = read_ply(src)
    hout, vout, fout, _ = read_ply(dst)
    vprops = lambda h: [l for l in h if l.startswith("property") and "list" not in l]
    if vprops(hin) != vprops(hout):  # another vertex layout: no record can be the input's
        print(f"{len(vout)} vertices wrong of {len(vout)}: written as {', '.join(p.split()[1] + ' ' + p.split()[2] for p in vprops(hout))}")
        return False
    # Output vertex -> input vertex by record bytes (every record of the test meshes differs).
    order = np.argsort(vin)
    found = np.minimum(np.searchsorted(vin[order], vout), len(vin) - 1)
    exact = vin[order][found] == vout
    wrong = int((~exact).sum())
    what = "vertices"
    if tex and wrong == 0:
        out_v = order[found]
        key = np.dtype([("v", "<i8"), ("u", "<u4"), ("w", "<u4")])

        def corners(vid, uv):
            k = np.zeros(vid.size, key)
            bits = uv.reshape(-1, 3, 2).view("<u4")
            k["v"], k["u"], k["w"] = vid.reshape(-1), bits[:, :, 0].reshape(-1), bits[:, :, 1].reshape(-1)
            return k.view(np.dtype((np.void, 16)))

        cin = np.unique(corners(fin["v"].astype(np.int64), fin["uv"]))
        cout = corners(out_v[fout["v"]], fout["uv"])
        wrong = int((~np.isin(cout, cin)).sum())
        what = "corners"
    print(f"{wrong} {what} wrong of {len(fout) * 3 if what == 'corners' else len(vout)}")
    return wrong == 0


def local(src, dst):
    header, vertices, faces, _ = read_ply(src)
    props = [l.split()[1:] for l in header if l.startswith("property") and "list" not in l]
    types = {"float": "<f4", "double": "<f8", "uchar": "u1", "char": "i1", "short": "<i2",
             "ushort": "<u2", "int": "<i4", "uint": "<u4"}
    dt = np.dtype([(name, types[t]) for t, name in props])
    rec = np.frombuffer(vertices.tobytes(), dt)
    xyz = np.stack([rec["x"], rec["y"], rec["z"]], 1).astype(np.float64)
    if rec.dtype["x"] == np.float64:
        xyz -= ORIGIN  # the same origin for every file: errors compare
    write_ply(dst, ["float x", "float y", "float z"], xyz.astype("<f4"), faces["v"])


if __name__ == "__main__":
    cmd = sys.argv[1]
    if cmd == "textured":
        textured(sys.argv[2], sys.argv[3])
    elif cmd == "colored":
        colored(sys.argv[2], sys.argv[3])
    elif cmd == "local":
        local(sys.argv[2], sys.argv[3])
    elif cmd == "check":
        sys.exit(0 if check(sys.argv[2], sys.argv[3]) else 1)
    else:
        sys.exit(__doc__)
