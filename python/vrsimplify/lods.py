"""Nested levels of detail in one run, and the streamable .glb that holds them all.

    import vrsimplify
    chain = vrsimplify.lods(vertices, faces, [1.0, 0.5, 0.1, 0.01])
    coarse = chain.levels[-1]
    coarse_vertices = chain.vertices[:coarse.vertex_count]   # rows of the input, untouched
    coarse.faces                                             # (k, 3) into those rows
    vrsimplify.write_glb("model.glb", vertices, chain, normals=normals)

Each level is simplified from the finer one, so its vertices are a subset of the finer level's;
``order`` lists the input vertices the coarsest level uses first, then those each finer level
adds: every level is a prefix of it. That is the layout ``write_glb`` streams.
"""
from __future__ import annotations

import dataclasses
import os
from typing import Optional, Sequence

import numpy as np

from . import _core


@dataclasses.dataclass(frozen=True)
class LodLevel:
    """One level of a chain."""

    ratio: float
    """The share of the input's faces asked for."""
    vertex_count: int
    """This level uses the first ``vertex_count`` entries of ``Lods.order``."""
    vertex_map: np.ndarray
    """(vertex_count,) int64: the level's vertex -> input vertex (a view of ``Lods.order``)."""
    faces: np.ndarray
    """(k, 3) int64: indices into ``Lods.order`` (and ``Lods.vertices``), all < vertex_count."""
    face_source: np.ndarray
    """(k,) int64: the input face an output face is, or -1 for a face the re-triangulation made."""
    corner_source: np.ndarray
    """(k, 3) int64: the input corner (3 * face + corner) whose per-corner data each corner takes."""
    report: dict
    """The run that made this level from the finer one (the keys of ``vrsimplify.Report``)."""


@dataclasses.dataclass(frozen=True)
class Lods:
    """A chain of nested levels: the shared vertex order and each level, finest first."""

    order: np.ndarray
    """(m,) int64: input vertex ids, the coarsest level's first, then each finer level's additions."""
    vertices: np.ndarray
    """(m, 3): the input's rows in that order, same dtype, bit for bit."""
    levels: list
    """``LodLevel`` per ratio, finest first (ratios sorted decreasing, repeats dropped)."""
    input_faces: int
    """Faces of the input (what per-corner arrays are indexed by)."""


def lods(mesh_vertices, mesh_faces, ratios: Sequence[float], /, *, mode: str = "surface",
         threads: int = 0, simplify_boundary: bool = False, keep_boundary: bool = False,
         max_jump: float = 10.0, feature_angle: float = 0.0, seams=None,
         corner_keys=None) -> Lods:
    """Simplifies to every ratio in one nested run (each level from the finer one).

    Each level's vertices are a subset of the finer level's; its error adds to the finer
    level's (each is measured against the level it was made from).

    Parameters
    ----------
    mesh_vertices, mesh_faces : array_like
        As ``vrsimplify.simplify``'s (triangles).
    ratios : sequence of float
        Shares of the input's faces in (0, 1]; 1 keeps the input as a level.
    mode, threads, max_jump, feature_angle, seams
        As ``vrsimplify.simplify``'s.
    simplify_boundary, keep_boundary : bool
        ``vrsimplify.simplify``'s ``boundary="simplify"`` and ``boundary="keep"``.
    corner_keys : array_like, (faces, 3), optional
        Integers, equal where two corners carry the same per-corner data (texture coordinates,
        normals): edges across which they differ are seams every level keeps.

    Returns
    -------
    Lods
        The shared vertex order, coarsest level first, and the levels.

    Raises
    ------
    ValueError
        Bad input or parameters.
    """
    from . import _array, _mesh_arrays

    v, f = _mesh_arrays(mesh_vertices, mesh_faces)
    try:
        rs = [float(r) for r in ratios]
    except (TypeError, ValueError):
        raise ValueError(f"ratios must be numbers in (0, 1], got {ratios!r}") from None
    if seams is not None:
        seams = _array(seams, "seams", "iu").astype(np.int64, copy=False)
    if corner_keys is not None:
        corner_keys = _array(corner_keys, "corner_keys", "iu").astype(np.int64, copy=False)
    order, levels = _core.lods(v, f, rs, str(mode), int(threads), bool(simplify_boundary),
                               bool(keep_boundary), float(max_jump), float(feature_angle), seams,
                               corner_keys)
    out = [LodLevel(ratio=r, vertex_count=int(n), vertex_map=order[:n], faces=fa.astype(np.int64),
                    face_source=fs, corner_source=cs, report=rep)
           for r, n, fa, fs, cs, rep in levels]
    return Lods(order=order, vertices=v[order], levels=out, input_faces=int(f.shape[0]))


def _rows(a, what):
    if a is None:
        return None
    a = np.asarray(a)
    if a.dtype.kind not in "fiu":
        raise ValueError(f"{what} must be numbers, got dtype {a.dtype}")
    if a.dtype.kind in "iu":  # 8-bit colors and the like: scaled to [0, 1]
        a = a / float(np.iinfo(a.dtype).max)
    return a.astype(np.float32, copy=False)


def write_glb(path, mesh_vertices, chain: Lods, /, *, normals=None, colors=None, uvs=None,
              corner_normals=None, corner_colors=None, corner_uvs=None,
              texture: Optional[str] = None, level_errors: Optional[Sequence[float]] = None,
              compress: bool = False) -> dict:
    """Writes every level of ``chain`` (of ``mesh_vertices``) as one binary glTF 2.0 file.

    One vertex buffer shared by all levels, coarsest level first; one index buffer per level;
    the levels bound by MSFT_lod. Written whole or not at all.

    Parameters
    ----------
    path : str or os.PathLike
        The ``.glb`` to write.
    mesh_vertices : array_like, (n, 3)
        The input's positions (the chain's vertices index them).
    chain : Lods
        What ``vrsimplify.lods`` returned for them.
    normals, colors, uvs : array_like, optional
        Per vertex, indexed like ``mesh_vertices``: normals (n, 3), colors (n, 3 or 4, floats
        in [0, 1] or 8-bit integers), texture coordinates (n, 2).
    corner_normals, corner_colors, corner_uvs : array_like, optional
        Per corner, indexed like the input's faces, (faces, 3, ...) or (3 * faces, ...); they
        take precedence. A vertex whose corners differ becomes one glTF vertex per distinct
        corner.
    texture : str, optional
        The base color image, as a path relative to the file.
    level_errors : sequence of float, optional
        One number per level (finest first), recorded in its mesh's extras and shown by the
        viewer page.
    compress : bool
        EXT_meshopt_compression (meshoptimizer's codec, lossless: positions stay the input's
        floats; the levels still stream coarsest first).

    Returns
    -------
    dict
        The layout: ``file_bytes``, ``compressed`` and per level ``faces``, ``vertices``,
        ``bytes_to_draw`` (what a reader with range requests fetches to draw it).
    """
    from . import _array

    v = _array(mesh_vertices, "vertices", "f")
    n, k = v.shape[0], chain.input_faces

    def per_vertex(a, what, width):
        a = _rows(a, what)
        if a is None:
            return None
        if what == "colors" and a.ndim == 2 and a.shape[1] == 3:
            a = np.hstack([a, np.ones((a.shape[0], 1), np.float32)])
        return a.reshape(n, width) if a.size == n * width else a

    def per_corner(a, what, width):
        a = _rows(a, what)
        if a is None:
            return None
        if what == "corner_colors" and a.shape[-1] == 3:
            a = np.concatenate([a, np.ones(a.shape[:-1] + (1,), np.float32)], axis=-1)
        return a.reshape(3 * k, width) if a.size == 3 * k * width else a

    corner = any(x is not None for x in (corner_normals, corner_colors, corner_uvs))
    layout = _core.write_glb(
        os.fspath(path), v, chain.order, [lv.ratio for lv in chain.levels],
        [lv.vertex_count for lv in chain.levels],
        [np.ascontiguousarray(lv.faces, dtype=np.int64) for lv in chain.levels],
        [np.ascontiguousarray(lv.corner_source, dtype=np.int64) for lv in chain.levels] if corner else [],
        per_vertex(normals, "normals", 3), per_vertex(colors, "colors", 4), per_vertex(uvs, "uvs", 2),
        per_corner(corner_normals, "corner_normals", 3), per_corner(corner_colors, "corner_colors", 4),
        per_corner(corner_uvs, "corner_uvs", 2), texture or "",
        [float(e) for e in level_errors] if level_errors is not None else [], k, bool(compress))
    return layout
