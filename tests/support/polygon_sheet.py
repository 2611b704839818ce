#!/usr/bin/env python3
"""A bent quad sheet with hexagons (two quads merged) and pentagons (a quad and half its
neighbour, the rest a triangle), as modelling tools write quad-dominant meshes, as an OFF of
polygons (41 x 41 vertices; 3200 triangles once split). No dependency beyond Python.

    polygon_sheet.py OUT.off
"""
import math
import sys

n = 40
vid = lambda i, j: j * (n + 1) + i  # noqa: E731
polys, used = [], set()
for j in range(0, n, 3):  # a hexagon and a pentagon with its triangle, by turns
    for i in range(0, n - 1, 5):
        used |= {(i, j), (i + 1, j)}
        if (i + j) % 2:
            polys.append([vid(i, j), vid(i + 1, j), vid(i + 2, j), vid(i + 2, j + 1),
                          vid(i + 1, j + 1), vid(i, j + 1)])
        else:
            polys += [[vid(i, j), vid(i + 1, j), vid(i + 2, j), vid(i + 1, j + 1), vid(i, j + 1)],
                      [vid(i + 2, j), vid(i + 2, j + 1), vid(i + 1, j + 1)]]
polys += [[vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)]
          for j in range(n) for i in range(n) if (i, j) not in used]
with open(sys.argv[1], "w") as f:
    f.write("OFF\n%d %d 0\n" % ((n + 1) ** 2, len(polys)))
    for j in range(n + 1):
        for i in range(n + 1):
            x, y = i / n, j / n
            f.write("%.6f %.6f %.6f\n" % (x, y, 0.1 * math.sin(3 * x) * math.cos(2 * y)))
    for p in polys:
        f.write("%d %s\n" % (len(p), " ".join(map(str, p))))
