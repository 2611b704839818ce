"""Textured test meshes with per-corner (wedge) texture coordinates, and the check that a
simplified one kept them.

    python textured_mesh.py make IN.off OUT.{ply,obj} [CHARTS]   # CHARTS planes cut the mesh
    python textured_mesh.py check INPUT OUTPUT                    # exit 1 when a corner is wrong

Charts: the faces are split by CHARTS (default 1) planes through the bounding box into up to
2**CHARTS charts. A corner's texture coordinate is its vertex's (x, y) scaled into [0, 1] plus
2 * chart in u, so it names both the vertex and the chart: seams lie between charts. The check
reads both files with pymeshlab (MeshLab's own readers) and requires, for every output face,
that each corner's coordinate is one its vertex had in the input, all three from one input
chart (faces joined across edges whose ends carry the same coordinates): it needs no knowledge
of how the input was made, so it checks real textured meshes too.
"""
import sys

import numpy as np


def read_off(path):
    words = []
    with open(path) as f:
        for line in f:
            line = line.split("#")[0]
            words += line.split()
    assert words[0].endswith("OFF"), path
    nv, nf = int(words[1]), int(words[2])
    at = 4
    v = np.array(words[at:at + 3 * nv], dtype=np.float64).reshape(nv, 3)
    at += 3 * nv
    faces = []
    for _ in range(nf):
        k = int(words[at])
        idx = [int(x) for x in words[at + 1:at + 1 + k]]
        at += 1 + k
        faces += [[idx[0], idx[j], idx[j + 1]] for j in range(1, k - 1)]
    return v.astype(np.float32), np.array(faces, dtype=np.int64)


def charts_of(v, f, planes):
    lo, hi = v.min(0), v.max(0)
    centroid = v[f].mean(1)
    rng = np.random.default_rng(3)
    chart = np.zeros(len(f), dtype=np.int64)
    for p in range(planes):
        normal = rng.normal(size=3)
        point = lo + (hi - lo) * (0.35 + 0.3 * p / max(1, planes - 1))
        chart |= ((centroid - point) @ normal > 0).astype(np.int64) << p
    return chart


def uv_of(v, lo, hi, chart):
    """Texture coordinate of vertex positions v (n x 3) in charts (n)."""
    span = np.maximum(hi - lo, 1e-30)
    uv = (v[:, :2] - lo[:2]) / span[:2]
    uv[:, 0] += 2 * chart
    return uv


def make(src, dst, planes):
    v, f = read_off(src)
    chart = charts_of(v, f, planes)
    lo, hi = v.min(0), v.max(0)
    uv = uv_of(v[f.reshape(-1)], lo, hi, np.repeat(chart, 3)).astype(np.float32)
    if dst.endswith(".ply"):
        with open(dst, "w") as out:
            out.write("ply\nformat ascii 1.0\n")
            out.write(f"element vertex {len(v)}\nproperty float x\nproperty float y\nproperty float z\n")
            out.write(f"element face {len(f)}\nproperty list uchar int vertex_indices\n")
            out.write("property list uchar float texcoord\nend_header\n")
            for p in v:
                out.write("%.9g %.9g %.9g\n" % tuple(p))
            for i, face in enumerate(f):
                t = uv[3 * i:3 * i + 3].reshape(-1)
                out.write("3 %d %d %d 6 %s\n" % (*face, " ".join("%.9g" % x for x in t)))
    else:  # OBJ: one vt per distinct (vertex, chart) corner value
        with open(dst, "w") as out:
            out.write(f"# charts {planes}\n")
            for p in v:
                out.write("v %.9g %.9g %.9g\n" % tuple(p))
            index = {}
            corners = []
            for c, (vi, ch) in enumerate(zip(f.reshape(-1), np.repeat(chart, 3))):
                key = (int(vi), int(ch))
                if key not in index:
                    index[key] = len(index) + 1
                    out.write("vt %.9g %.9g\n" % (uv[c, 0], uv[c, 1]))
                corners.append(index[key])
            for i, face in enumerate(f):
                out.write("f %d/%d %d/%d %d/%d\n" % (face[0] + 1, corners[3 * i], face[1] + 1,
                                                     corners[3 * i + 1], face[2] + 1,
                                                     corners[3 * i + 2]))
    print(f"{dst}: {len(v)} vertices, {len(f)} faces, {len(set(chart.tolist()))} charts")


def load(path):
    import pymeshlab
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(path)
    m = ms.current_mesh()
    assert m.has_wedge_tex_coord(), f"{path} has no per-corner texture coordinates"
    return (m.vertex_matrix().astype(np.float32), m.face_matrix(),
            m.wedge_tex_coord_matrix().reshape(-1, 3, 2))


def charts(faces, uv):
    """Chart of each input face: faces joined across edges whose two ends carry the same
    texture coordinate in both faces. Returns the chart ids."""
    parent = list(range(len(faces)))

    def find(f):
        while parent[f] != f:
            parent[f] = parent[parent[f]]
            f = parent[f]
        return f

    first = {}
    for f, face in enumerate(faces.tolist()):
        for c in range(3):
            a, b = face[c], face[(c + 1) % 3]
            key = (min(a, b), max(a, b))
            here = {a: uv[f, c], b: uv[f, (c + 1) % 3]}
            if key not in first:
                first[key] = (f, here)
                continue
            g, there = first[key]
            if all(np.array_equal(here[v], there[v]) for v in (a, b)):
                parent[find(f)] = find(g)
    return [find(f) for f in range(len(faces))]


def check(src, dst):
    """Every output corner carries a texture coordinate its vertex had in the input, and the
    three corners of a face carry values of one input chart."""
    vi, fi, wi = load(src)
    vo, fo, wo = load(dst)
    wi, wo = np.round(wi, 5), np.round(wo, 5)  # text formats round; the charts do not care
    chart = charts(fi, wi)
    # Keyed by position: a file may hold several vertices at one place (split at seams).
    values = {}  # (input position, uv) -> charts where a vertex there has that value
    for f, face in enumerate(fi.tolist()):
        for c in range(3):
            values.setdefault((tuple(vi[face[c]].tolist()), tuple(wi[f, c])), set()).add(chart[f])
    bad = 0
    for face, uv in zip(fo.tolist(), wo):
        common = None
        for c in range(3):
            found = values.get((tuple(vo[face[c]].tolist()), tuple(uv[c])), set())
            common = found if common is None else common & found
        bad += not common
    share = 100.0 * (len(fo) - bad) / max(1, len(fo))
    print(f"{dst}: {len(fi)} -> {len(fo)} faces, {share:.2f} % of faces whose corners carry "
          f"texture coordinates of their vertex in one input chart ({bad} wrong)")
    return bad == 0 and len(fo) < len(fi)


if __name__ == "__main__":
    if sys.argv[1] == "make":
        make(sys.argv[2], sys.argv[3], int(sys.argv[4]) if len(sys.argv) > 4 else 1)
    elif sys.argv[1] == "check":
        sys.exit(0 if check(sys.argv[2], sys.argv[3]) else 1)
    else:
        sys.exit(__doc__)
