#!/usr/bin/env python3
"""A bent quad sheet with hexagons (two quads merged) and pentagons (a quad and half its
neighbour, the rest a triangle), as modelling tools write quad-dominant meshes: 41 x 41
vertices, 3200 triangles once split. As OFF (polygons only) or as OBJ (with a texture
coordinate per vertex, the sheet's own x, y), by the output's extension. No dependency beyond
Python; the MeshLab tests (meshlabserver, the GUIs, pymeshlab) all use this one sheet.

    polygon_sheet.py OUT.off|OUT.obj
"""
import math
import sys


def sheet(n=40):
    """(positions, polygons): (x, y, z) per vertex, and the polygons as 0-based vertex lists."""
    vid = lambda i, j: j * (n + 1) + i  # noqa: E731
    polys, used = [], set()
    for j in range(0, n, 3):  # a hexagon and a pentagon with its triangle, by turns
        for i in range(0, n - 1, 5):
            used |= {(i, j), (i + 1, j)}
            if (i + j) % 2:
                polys.append([vid(i, j), vid(i + 1, j), vid(i + 2, j), vid(i + 2, j + 1),
                              vid(i + 1, j + 1), vid(i, j + 1)])
            else:
                polys += [[vid(i, j), vid(i + 1, j), vid(i + 2, j), vid(i + 1, j + 1),
                           vid(i, j + 1)],
                          [vid(i + 2, j), vid(i + 2, j + 1), vid(i + 1, j + 1)]]
    polys += [[vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)]
              for j in range(n) for i in range(n) if (i, j) not in used]
    positions = [(i / n, j / n, 0.1 * math.sin(3 * i / n) * math.cos(2 * j / n))
                 for j in range(n + 1) for i in range(n + 1)]
    return positions, polys


def write(path):
    positions, polys = sheet()
    with open(path, "w") as f:
        if str(path).endswith(".obj"):
            for x, y, z in positions:
                f.write("v %.6f %.6f %.6f\nvt %.6f %.6f\n" % (x, y, z, x, y))
            for p in polys:
                f.write("f %s\n" % " ".join("%d/%d" % (v + 1, v + 1) for v in p))
            return
        f.write("OFF\n%d %d 0\n" % (len(positions), len(polys)))
        for x, y, z in positions:
            f.write("%.6f %.6f %.6f\n" % (x, y, z))
        for p in polys:
            f.write("%d %s\n" % (len(p), " ".join(map(str, p))))


if __name__ == "__main__":
    write(sys.argv[1])
