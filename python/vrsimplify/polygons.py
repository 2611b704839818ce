"""Polygon faces for the numpy API: fanned into triangles for the core (each from its first
corner, as the command line reads OBJ, PLY and OFF polygons), and the polygons a run left
untouched put back whole, as MeshLab's filter keeps its quads."""
from __future__ import annotations

import dataclasses
from typing import Optional

import numpy as np


@dataclasses.dataclass(frozen=True)
class Fanned:
    """Polygons as the core's triangles, and where each triangle came from."""

    triangles: np.ndarray  # (t, 3) int64
    polygon: np.ndarray  # (t,) int64: the input face each triangle is part of
    corner: np.ndarray  # (t, 3) int64: each triangle corner's input corner (flattened)
    corners: np.ndarray  # every input face's corners, one after the other
    first: np.ndarray  # (p + 1,): face p's corners are corners[first[p]:first[p + 1]]

    @property
    def whole_flags(self) -> np.ndarray:
        """Per triangle: part of a polygon of four corners or more (the core's polygon_faces)."""
        return np.diff(self.first)[self.polygon] > 3


def polygon_faces(faces) -> Optional[tuple[np.ndarray, np.ndarray]]:
    """(corners, first) when `faces` holds polygons: a (k, m) array with m > 3, or a sequence
    of faces of different lengths; None for a (k, 3) array (triangles, the core's own)."""
    if isinstance(faces, np.ndarray) and faces.dtype != object:
        if faces.ndim == 2 and faces.shape[1] > 3:
            if faces.dtype.kind not in "iu":
                raise ValueError(f"faces has dtype {faces.dtype}, expected integers")
            k, m = faces.shape
            return faces.reshape(-1), np.arange(k + 1, dtype=np.int64) * m
        return None  # the core checks its shape and says what it expects
    try:
        a = np.asarray(faces)
        if a.dtype != object:
            return polygon_faces(a)
    except ValueError:  # faces of different lengths
        pass
    rows = [np.asarray(f).reshape(-1) for f in faces]
    for i, r in enumerate(rows):
        if r.dtype.kind not in "iu":
            raise ValueError(f"face {i} has dtype {r.dtype}, expected integers")
        if len(r) < 3:
            raise ValueError(f"face {i} has {len(r)} corners: a face needs 3 or more")
    first = np.zeros(len(rows) + 1, dtype=np.int64)
    np.cumsum([len(r) for r in rows], out=first[1:])
    corners = np.concatenate(rows) if rows else np.zeros(0, dtype=np.int64)
    return corners, first


def fan(corners: np.ndarray, first: np.ndarray, vertex_count: int) -> Fanned:
    """Each face (c0, c1, ..., cm-1) as the triangles (c0, ci, ci+1); indices checked first, so
    that a message names the face, not a triangle."""
    corners = corners.astype(np.int64, copy=False)
    sizes = np.diff(first)
    bad = np.flatnonzero(sizes < 3)
    if len(bad):
        raise ValueError(f"face {bad[0]} has {sizes[bad[0]]} corners: a face needs 3 or more")
    out = np.flatnonzero((corners < 0) | (corners >= vertex_count))
    if len(out):
        face = int(np.searchsorted(first, out[0], side="right")) - 1
        raise ValueError(f"face {face} has vertex index {corners[out[0]]}, out of range for "
                         f"{vertex_count} vertices")
    fans = sizes - 2  # triangles a face
    polygon = np.repeat(np.arange(len(sizes), dtype=np.int64), fans)
    # Triangle j of its face: corners 0, j + 1, j + 2 of the face.
    j = np.arange(len(polygon), dtype=np.int64) - np.repeat(np.cumsum(fans) - fans, fans)
    base = first[:-1][polygon]
    corner = np.stack([base, base + j + 1, base + j + 2], axis=1)
    return Fanned(triangles=corners[corner], polygon=polygon, corner=corner, corners=corners,
                  first=first)


def regroup(fanned: Fanned, faces: np.ndarray, face_source: np.ndarray, vertex_map: np.ndarray,
            vertex_count: int) -> tuple[list, np.ndarray]:
    """The output as polygons: an input polygon every triangle of which the run left untouched
    comes back whole (at its first triangle's place), every other face as a triangle. Returns
    the polygons (output vertex indices) and each one's input face (-1: made by the run)."""
    untouched = face_source >= 0
    t = np.maximum(face_source, 0)
    polygon = np.where(untouched, fanned.polygon[t], -1)
    sizes = np.diff(fanned.first)
    kept = np.bincount(polygon[untouched], minlength=len(sizes))
    whole = (kept == sizes - 2) & (sizes > 3)
    in_whole = untouched & whole[np.maximum(polygon, 0)]
    lead = in_whole & (fanned.corner[t, 1] == fanned.corner[t, 0] + 1)  # its fan's first
    output_of = np.full(vertex_count, -1, dtype=np.int64)
    output_of[vertex_map] = np.arange(len(vertex_map))
    polygons, source = [], []
    for i in np.flatnonzero(~in_whole | lead):
        p = polygon[i]
        if lead[i]:
            corners = fanned.corners[fanned.first[p]:fanned.first[p + 1]]
            polygons.append(output_of[corners].astype(faces.dtype, copy=False))
        else:
            polygons.append(faces[i])
        source.append(p)
    return polygons, np.asarray(source, dtype=np.int64)


def input_sources(fanned: Fanned, face_source: np.ndarray,
                  corner_source: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """face_source and corner_source in terms of the input's polygons and their corners (a
    face's corners one after the other, as `corners`) instead of the fanned triangles."""
    faces = np.where(face_source >= 0, fanned.polygon[np.maximum(face_source, 0)], -1)
    flat = fanned.corner.reshape(-1)
    corners = np.where(corner_source >= 0, flat[np.maximum(corner_source, 0)], -1)
    return faces, corners
