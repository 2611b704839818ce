"""Progressive meshes: a base and one insertion a removed vertex, coarsest first.

    import vrsimplify
    p = vrsimplify.progressive(vertices, faces)
    coarse = p.faces_after(0)           # the base: (input faces, 3) input vertex ids, -1: empty
    finer = p.faces_after(1000)         # after 1 000 insertions
    assert (p.faces_after(p.insertions) == faces).all()   # up to each face's rotation

An insertion undoes one removal: its vertex comes back and its fan of faces replaces the patch
that filled the hole. Faces live in slots, one an input face, so after every insertion slot f
holds input face f again. ``read_progressive`` decodes the .glb the command line writes
(``vrsimplify IN OUT.glb --progressive``; docs/progressive.md): it is the format's reference
decoder, in plain Python and numpy, exact and slow on millions of records.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import _core
from .progressive_file import EXTENSION, ProgressiveFile, read_progressive  # noqa: F401


@dataclass(frozen=True)
class Progressive:
    """A base mesh and its insertions, as arrays (corners name input corners, 3 * face + c).

    Attributes
    ----------
    base_slots : numpy.ndarray
        ``(b,)`` int64: the slots (input faces) the base's faces stand in, increasing.
    base_corners : numpy.ndarray
        ``(b, 3)`` int64: each base face's input corners; ``faces.flat[corner]`` is its vertex.
    vertex : numpy.ndarray
        ``(r,)`` int64: the input vertex insertion i brings back.
    first : numpy.ndarray
        ``(r + 1,)`` int64: insertion i writes faces ``first[i]`` to ``first[i + 1]``.
    slots : numpy.ndarray
        ``(w,)`` int64: the slot each written face goes to.
    corners : numpy.ndarray
        ``(w, 3)`` int64: each written face's input corners.
    report : dict
        The run that made the base (the keys of ``vrsimplify.Report``).
    input_faces : numpy.ndarray
        The input's ``(n, 3)`` faces, which the corners index.
    """

    base_slots: np.ndarray
    base_corners: np.ndarray
    vertex: np.ndarray
    first: np.ndarray
    slots: np.ndarray
    corners: np.ndarray
    report: dict
    input_faces: np.ndarray

    @property
    def insertions(self) -> int:
        """The number of insertions."""
        return int(self.vertex.shape[0])

    def corners_after(self, count: int) -> np.ndarray:
        """``(input faces, 3)`` input corners of each slot after ``count`` insertions; -1: empty."""
        if not 0 <= count <= self.insertions:
            raise ValueError(f"count must be in [0, {self.insertions}], got {count}")
        out = np.full((self.input_faces.shape[0], 3), -1, dtype=np.int64)
        out[self.base_slots] = self.base_corners
        w = int(self.first[count])
        if w:
            # Each slot takes the last face written to it.
            last = np.full(out.shape[0], -1, dtype=np.int64)
            np.maximum.at(last, self.slots[:w], np.arange(w, dtype=np.int64))
            hit = last >= 0
            out[hit] = self.corners[last[hit]]
        return out

    def faces_after(self, count: int) -> np.ndarray:
        """``(input faces, 3)`` input vertex ids of each slot after ``count`` insertions; -1: empty."""
        corners = self.corners_after(count)
        flat = self.input_faces.reshape(-1)
        return np.where(corners >= 0, flat[np.maximum(corners, 0)], -1)


def progressive(mesh_vertices, mesh_faces, /, *, base: float = 0.003, mode: str = "surface",
                simplify_boundary: bool = False, keep_boundary: bool = False,
                max_jump: float = 10.0, feature_angle: float = 0.0, seams=None,
                corner_keys=None) -> Progressive:
    """Simplifies to ``base`` of the faces, recording every removal as an insertion.

    Runs on one thread, without the slide (it would move a kept vertex after the removals
    recorded), so the base can differ from ``vrsimplify.simplify``'s output by the slide.

    Parameters
    ----------
    mesh_vertices, mesh_faces : array_like
        As ``vrsimplify.simplify``'s (triangles).
    base : float
        The base's share of the input's faces, in (0, 1].
    mode, max_jump, feature_angle, seams
        As ``vrsimplify.simplify``'s.
    simplify_boundary, keep_boundary : bool
        ``vrsimplify.simplify``'s ``boundary="simplify"`` and ``boundary="keep"``.
    corner_keys : array_like, (faces, 3), optional
        Integers, equal where two corners carry the same per-corner data: edges across which
        they differ are seams the base and every prefix keep.

    Returns
    -------
    Progressive

    Raises
    ------
    ValueError
        Bad input or parameters.
    """
    from . import _array, _mesh_arrays

    if not 0 < float(base) <= 1:
        raise ValueError(f"base must be in (0, 1], got {base!r}")
    v, f = _mesh_arrays(mesh_vertices, mesh_faces)
    if seams is not None:
        seams = _array(seams, "seams", "iu").astype(np.int64, copy=False)
    if corner_keys is not None:
        corner_keys = _array(corner_keys, "corner_keys", "iu").astype(np.int64, copy=False)
    bs, bc, vertex, first, slots, corners, report = _core.progressive(
        v, f, float(base), str(mode), bool(simplify_boundary), bool(keep_boundary),
        float(max_jump), float(feature_angle), seams, corner_keys)
    return Progressive(base_slots=bs, base_corners=bc, vertex=vertex, first=first, slots=slots,
                       corners=corners, report=report,
                       input_faces=np.asarray(f, dtype=np.int64).reshape(-1, 3))
