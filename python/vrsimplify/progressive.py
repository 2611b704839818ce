"""Progressive meshes: a base and one insertion a removed vertex, coarsest first.

    import vrsimplify
    p = vrsimplify.progressive(vertices, faces, base=0.01)
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

import json
import struct
from dataclasses import dataclass

import numpy as np

from . import _core

EXTENSION = "VRS_mesh_progressive"
_CLOSED_FAN, _OPEN_FAN, _LISTED_RING = 1, 2, 3


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


def progressive(mesh_vertices, mesh_faces, /, *, base: float = 0.01, mode: str = "surface",
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


@dataclass
class ProgressiveFile:
    """A progressive mesh decoded up to some record.

    Attributes
    ----------
    vertices : numpy.ndarray
        The glTF vertices decoded so far, one interleaved record a row (``uint8``, ``stride``
        bytes): see :meth:`positions` and :meth:`attribute`.
    faces : numpy.ndarray
        ``(F, 3)`` indices into ``vertices``, one face a slot.
    applied, insertions : int
        The records applied and the records the file announces.
    complete_faces, complete_vertices : int
        The face and vertex counts once every record is applied.
    layout : dict
        Offsets (``normal``, ``color``, ``uv``; ``None`` when absent) and ``stride``.
    """

    vertices: np.ndarray
    faces: np.ndarray
    applied: int
    insertions: int
    complete_faces: int
    complete_vertices: int
    layout: dict

    def positions(self) -> np.ndarray:
        """``(V, 3)`` float32 positions."""
        return self.attribute("position", 3, np.float32)

    def attribute(self, name: str, width: int, dtype) -> np.ndarray | None:
        """The attribute ``name`` (``position``, ``normal``, ``color``, ``uv``) as ``(V, width)``."""
        at = 0 if name == "position" else self.layout.get(name)
        if at is None:
            return None
        size = np.dtype(dtype).itemsize * width
        raw = np.ascontiguousarray(self.vertices[:, at : at + size])
        return raw.view(dtype).reshape(-1, width)


def _varint(buf: bytes, at: int) -> tuple[int, int]:
    value = shift = 0
    while True:
        if at >= len(buf):
            raise EOFError
        b = buf[at]
        at += 1
        value |= (b & 0x7F) << shift
        if b < 0x80:
            return value, at
        shift += 7


def _chunks(data: bytes) -> tuple[dict, bytes]:
    magic, version, _ = struct.unpack_from("<III", data, 0)
    if magic != 0x46546C67 or version != 2:
        raise ValueError("not a binary glTF 2.0 file")
    json_len, json_type = struct.unpack_from("<II", data, 12)
    if json_type != 0x4E4F534A:
        raise ValueError("the first chunk of a .glb is its JSON")
    doc = json.loads(data[20 : 20 + json_len])
    at = 20 + json_len
    bin_len, _ = struct.unpack_from("<II", data, at)
    return doc, data[at + 8 : at + 8 + bin_len]


def read_progressive(source, records: int | None = None) -> ProgressiveFile:
    """Decode a progressive .glb: its base mesh and then ``records`` insertions (all by default).

    Parameters
    ----------
    source : str, os.PathLike or bytes
        The file, or its bytes. A prefix of the file decodes too: the records it holds whole
        are applied (the base must be there).
    records : int, optional
        How many insertion records to apply at most.

    Returns
    -------
    ProgressiveFile
    """
    data = source if isinstance(source, (bytes, bytearray, memoryview)) else open(source, "rb").read()
    data = bytes(data)
    doc, binary = _chunks(data)
    prim = doc["meshes"][0]["primitives"][0]
    ext = prim.get("extensions", {}).get(EXTENSION)
    if ext is None:
        raise ValueError("the file has no %s extension" % EXTENSION)
    acc = doc["accessors"]
    views = doc["bufferViews"]
    pos = acc[prim["attributes"]["POSITION"]]
    vview = views[pos["bufferView"]]
    stride = vview["byteStride"]
    layout = {"stride": stride, "normal": None, "color": None, "uv": None}
    for key, name in (("NORMAL", "normal"), ("COLOR_0", "color"), ("TEXCOORD_0", "uv")):
        if key in prim["attributes"]:
            layout[name] = acc[prim["attributes"][key]].get("byteOffset", 0)
    base_count = pos["count"]
    start = vview.get("byteOffset", 0)
    base_vertices = np.frombuffer(binary[start : start + base_count * stride], np.uint8)
    base_vertices = base_vertices.reshape(base_count, stride)
    ia = acc[prim["indices"]]
    iview = views[ia["bufferView"]]
    dtype = np.uint32 if ia["componentType"] == 5125 else np.uint16
    istart = iview.get("byteOffset", 0) + ia.get("byteOffset", 0)
    faces = np.frombuffer(binary[istart : istart + ia["count"] * dtype().itemsize], dtype)
    sview = views[ext["bufferView"]]
    stream = binary[sview.get("byteOffset", 0) : sview.get("byteOffset", 0) + sview["byteLength"]]

    vertex_rows = [base_vertices]
    vertex_count = base_count
    live = [list(map(int, faces[i : i + 3])) for i in range(0, len(faces), 3)]
    limit = ext["insertions"] if records is None else min(records, ext["insertions"])
    at = applied = 0
    try:
        while applied < limit:
            at = _apply_record(stream, at, stride, live, vertex_rows, vertex_count)
            vertex_count = sum(len(r) for r in vertex_rows)
            applied += 1
    except EOFError:  # a prefix of the file: the last record is not whole
        pass
    vertices = np.concatenate(vertex_rows) if len(vertex_rows) > 1 else base_vertices
    return ProgressiveFile(
        vertices=vertices,
        faces=np.asarray(live, dtype=np.int64).reshape(-1, 3),
        applied=applied,
        insertions=ext["insertions"],
        complete_faces=ext["faceCount"],
        complete_vertices=ext["vertexCount"],
        layout=layout,
    )


def _apply_record(stream, at, stride, live, vertex_rows, before):
    """Applies the record at ``at``; returns where the next begins (EOFError: not whole)."""
    head, at = _varint(stream, at)
    k, shape, irregular = head >> 3, (head >> 1) & 3, head & 1
    added, apex_ref = 1, 0
    if irregular:
        added, at = _varint(stream, at)
        if shape:
            apex_ref, at = _varint(stream, at)
    if at + added * stride > len(stream):
        raise EOFError
    new_rows = np.frombuffer(stream[at : at + added * stride], np.uint8).reshape(added, stride)
    at += added * stride
    if shape in (_CLOSED_FAN, _OPEN_FAN):
        reused = k - 2 if shape == _CLOSED_FAN else k - 1
    else:
        reused, at = _varint(stream, at)
    count = len(live)
    slots = []
    for _ in range(reused):
        back, at = _varint(stream, at)
        slots.append(count - 1 - back)
    patch = [v for s in slots for v in live[s]]

    def vertex(ref):
        if ref < added:
            return before + ref
        if ref < added + len(patch):
            return patch[ref - added]
        return before - 1 - (ref - added - len(patch))

    if shape in (_CLOSED_FAN, _OPEN_FAN):
        first, at = _varint(stream, at)
        following = {}
        for t in range(0, len(patch), 3):
            for c in range(3):
                following[(patch[t + c])] = following.get(patch[t + c], []) + [patch[t + (c + 1) % 3]]
        # The outline: each side the patch walks once and never back.
        sides = {(patch[t + c], patch[t + (c + 1) % 3]) for t in range(0, len(patch), 3) for c in range(3)}
        ring = [vertex(first)]
        while len(ring) < (k if shape == _CLOSED_FAN else k + 1):
            a = ring[-1]
            nxt = [b for b in following.get(a, []) if (b, a) not in sides]
            ring.append(nxt[0])
        apex = vertex(apex_ref)
        n = len(ring)
        new_faces = [[apex, ring[i], ring[(i + 1) % n]] for i in range(k)]
    elif shape == _LISTED_RING:
        open_, at = _varint(stream, at)
        ring = []
        for _ in range(k + open_):
            r, at = _varint(stream, at)
            ring.append(vertex(r))
        apex = vertex(apex_ref)
        n = len(ring)
        new_faces = [[apex, ring[i], ring[(i + 1) % n]] for i in range(k)]
    else:
        new_faces = []
        for _ in range(k):
            f = []
            for _ in range(3):
                r, at = _varint(stream, at)
                f.append(vertex(r))
            new_faces.append(f)
    vertex_rows.append(new_rows)
    for i, f in enumerate(new_faces):
        if i < reused:
            live[slots[i]] = f
        else:
            live.append(f)
    return at
