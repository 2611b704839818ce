"""The progressive .glb's reference decoder (docs/progressive.md), in plain Python and numpy:
exact, and slow on millions of records. No import of the package's compiled core, so that
tools can load this file alone."""

from __future__ import annotations

import json
import struct
from dataclasses import dataclass

import numpy as np

EXTENSION = "VRS_mesh_progressive"
_CLOSED_FAN, _OPEN_FAN, _LISTED_RING = 1, 2, 3


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
            at, added = _apply_record(stream, at, stride, live, vertex_rows, vertex_count)
            vertex_count += added
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
    """Applies the record at ``at``; returns where the next begins and the vertices it added
    (EOFError: the record is not whole)."""
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
        # The outline: each side the patch walks once and never back.
        sides = {(patch[t + c], patch[t + (c + 1) % 3]) for t in range(0, len(patch), 3) for c in range(3)}
        outline = {a: b for a, b in sides if (b, a) not in sides}
        ring = [vertex(first)]
        while len(ring) < (k if shape == _CLOSED_FAN else k + 1):
            ring.append(outline[ring[-1]])
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
    return at, added
