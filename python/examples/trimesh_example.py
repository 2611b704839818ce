"""Simplify a colored mesh with trimesh and vrsimplify: the colors stay exactly the input's.

    python trimesh_example.py [IN] [OUT.ply] [RATIO]

Without arguments it makes a colored sphere and writes sphere-10.ply.
"""
import sys

import numpy as np
import trimesh

import vrsimplify.trimesh

if len(sys.argv) > 1 and sys.argv[1]:
    mesh = trimesh.load(sys.argv[1], force="mesh")
else:
    mesh = trimesh.creation.icosphere(subdivisions=5)
    rgb = (127 * (mesh.vertices + 1)).astype(np.uint8)  # color by position
    mesh.visual.vertex_colors = np.c_[rgb, np.full(len(rgb), 255, np.uint8)]
out = sys.argv[2] if len(sys.argv) > 2 else "sphere-10.ply"
ratio = float(sys.argv[3]) if len(sys.argv) > 3 else 0.1

small = vrsimplify.trimesh.simplify_trimesh(mesh, ratio=ratio)
report = small.metadata["vrsimplify"]["report"]
print(f"{len(mesh.faces)} -> {len(small.faces)} faces ({report['stop_reason']}); "
      f"{len(small.vertices)} vertices, each an input vertex with its own color")
small.export(out)
print(f"wrote {out}")
