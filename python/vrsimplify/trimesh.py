"""trimesh meshes through vrsimplify: the simplified mesh keeps the input's vertex colors, UVs
(with the material), per-vertex attributes and face colors exactly, through the result's maps.

    import trimesh, vrsimplify.trimesh
    small = vrsimplify.trimesh.simplify_trimesh(trimesh.load("in.ply"), ratio=0.1)
"""
from __future__ import annotations

import numpy as np
import trimesh

from . import Result, simplify

__all__ = ["simplify_trimesh"]


def _visual(mesh: trimesh.Trimesh, r: Result):
    visual = mesh.visual
    if visual is None or not visual.defined:
        return None
    if visual.kind == "vertex":
        return trimesh.visual.ColorVisuals(vertex_colors=visual.vertex_colors[r.vertex_map])
    if visual.kind == "face":
        # A new face takes the color of the input face its first corner comes from.
        source = np.where(r.face_source >= 0, r.face_source, r.corner_source[:, 0] // 3)
        return trimesh.visual.ColorVisuals(face_colors=visual.face_colors[source])
    if visual.kind == "texture" and getattr(visual, "uv", None) is not None:
        return trimesh.visual.TextureVisuals(uv=visual.uv[r.vertex_map], material=visual.material)
    return None


def simplify_trimesh(mesh: trimesh.Trimesh, **options) -> trimesh.Trimesh:
    """Simplified copy of `mesh` (options as vrsimplify.simplify; the input is untouched).

    The result's ``metadata["vrsimplify"]`` holds the report and ``vertex_map``. trimesh splits
    vertices along UV seams on load: those seams are borders to the core, kept unless
    ``simplify_boundary=True``.
    """
    r = simplify(mesh.vertices, mesh.faces, **options)
    out = trimesh.Trimesh(vertices=r.vertices, faces=r.faces, process=False,
                          visual=_visual(mesh, r),
                          vertex_attributes={k: np.asarray(v)[r.vertex_map]
                                             for k, v in mesh.vertex_attributes.items()})
    out.metadata.update(mesh.metadata)
    out.metadata["vrsimplify"] = {"report": r.report, "vertex_map": r.vertex_map}
    return out
