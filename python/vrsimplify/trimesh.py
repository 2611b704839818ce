"""trimesh meshes through vrsimplify: the simplified mesh keeps the input's vertex colors, UVs
(with the material), per-vertex attributes and face colors exactly, through the result's maps.

    import trimesh, vrsimplify.trimesh
    small = vrsimplify.trimesh.simplify_trimesh(trimesh.load("in.ply"), ratio=0.1)
"""
from __future__ import annotations

import copy

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
        # A copy, as the rest of the result: editing the output's material leaves the input's.
        return trimesh.visual.TextureVisuals(uv=visual.uv[r.vertex_map],
                                             material=copy.deepcopy(visual.material))
    return None


def _region_borders(mesh: trimesh.Trimesh) -> np.ndarray | None:
    """Edges between faces of different face colour or face attribute, as (s, 2) vertex pairs:
    kept as polylines, so that no region's colour (or label) bleeds into its neighbour's."""
    labels = []
    visual = mesh.visual
    if visual is not None and visual.defined and visual.kind == "face":
        labels.append(np.asarray(visual.face_colors).reshape(len(mesh.faces), -1))
    for value in mesh.face_attributes.values():
        value = np.asarray(value)
        if len(value) == len(mesh.faces):
            labels.append(value.reshape(len(mesh.faces), -1))
    if not labels:
        return None
    key = np.concatenate([np.ascontiguousarray(l).view(np.uint8).reshape(len(mesh.faces), -1)
                          for l in labels], axis=1)
    pairs = mesh.face_adjacency  # (p, 2) faces sharing an edge
    differ = np.any(key[pairs[:, 0]] != key[pairs[:, 1]], axis=1)
    return np.asarray(mesh.face_adjacency_edges[differ], dtype=np.int64).reshape(-1, 2)


def _simplify_one(mesh: trimesh.Trimesh, options: dict) -> trimesh.Trimesh:
    seams = _region_borders(mesh)
    if seams is not None and len(seams):
        given = options.get("seams")
        options = {**options, "seams": seams if given is None else np.concatenate(
            [np.asarray(given, dtype=np.int64).reshape(-1, 2), seams])}
    r = simplify(mesh.vertices, mesh.faces, **options)
    source = np.where(r.face_source >= 0, r.face_source, r.corner_source[:, 0] // 3)
    out = trimesh.Trimesh(vertices=r.vertices, faces=r.faces, process=False,
                          visual=_visual(mesh, r),
                          vertex_attributes={k: np.asarray(v)[r.vertex_map]
                                             for k, v in mesh.vertex_attributes.items()},
                          face_attributes={k: np.asarray(v)[source]
                                           for k, v in mesh.face_attributes.items()
                                           if len(np.asarray(v)) == len(mesh.faces)})
    out.metadata.update(mesh.metadata)
    out.metadata["vrsimplify"] = {"report": r.report, "vertex_map": r.vertex_map}
    return out


def simplify_trimesh(mesh, **options):
    """Simplified copy of `mesh` (options as vrsimplify.simplify; the input is untouched).

    A ``trimesh.Trimesh`` gives a ``Trimesh``; a ``trimesh.Scene`` (what ``trimesh.load``
    returns for multi-part files) gives a ``Scene`` with each part simplified by the same
    options and placed as before. The result's ``metadata["vrsimplify"]`` holds the report and
    ``vertex_map``. Borders between faces of different face colour or face attribute are kept
    as seams (a new face takes a colour from the region it lies in); ``face_attributes`` follow
    their faces. trimesh splits vertices along UV seams on load: those seams stay.
    """
    if isinstance(mesh, trimesh.Scene):
        # A new scene over a copy of the same graph (Scene.copy() would copy every part first).
        parts = {name: _simplify_one(g, options)
                 if isinstance(g, trimesh.Trimesh) and len(g.faces) else g
                 for name, g in mesh.geometry.items()}
        return trimesh.Scene(parts, base_frame=mesh.graph.base_frame,
                             metadata=dict(mesh.metadata), graph=mesh.graph.copy())
    if not isinstance(mesh, trimesh.Trimesh):
        raise TypeError(f"simplify_trimesh takes a trimesh.Trimesh or trimesh.Scene, not "
                        f"{type(mesh).__name__}")
    return _simplify_one(mesh, options)
