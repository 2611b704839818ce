"""The progressive .glb's reference decoder (docs/progressive.md), in plain Python and numpy:
exact, and slow on millions of records. No import of the package's compiled core, so that
tools can load this file alone."""

from __future__ import annotations

import json
import math
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


_RICE_ESCAPE, _RICE_SPREAD_SHIFT = 16, 3


class _Bits:
    """A record's run of bits, lowest bit of each byte first, from byte ``at``."""

    def __init__(self, buf: bytes, at: int):
        self.buf, self.pos = buf, 8 * at

    def bit(self) -> int:
        if self.pos >> 3 >= len(self.buf):
            raise EOFError
        b = self.buf[self.pos >> 3] >> (self.pos & 7) & 1
        self.pos += 1
        return b

    def bits(self, n: int) -> int:
        return sum(self.bit() << i for i in range(n))

    def rice(self, k: int) -> int:
        """A Rice code of parameter ``k``, its escape included."""
        q = 0
        while q < _RICE_ESCAPE and self.bit():
            q += 1
        if q < _RICE_ESCAPE:
            return q << k | self.bits(k)
        return self.bits(self.bits(6))

    def end(self) -> int:
        """The byte after the run (its last byte padded)."""
        return (self.pos + 7) >> 3


def _rice_parameter(spread: int) -> int:
    return max(0, spread.bit_length() - _RICE_SPREAD_SHIFT)


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

    if ext.get("version") != 3:
        raise ValueError("a %s stream of version %s: this reader knows version 3" % (EXTENSION, ext.get("version")))
    state = _State(faces, base_vertices.tobytes(), stride, layout)
    limit = ext["insertions"] if records is None else min(records, ext["insertions"])
    at = applied = 0
    try:
        while applied < limit:
            at = state.apply(stream, at)
            applied += 1
    except EOFError:  # a prefix of the file: the last record is not whole
        pass
    vertices = np.frombuffer(bytes(state.vertices), np.uint8).reshape(-1, stride)
    return ProgressiveFile(
        vertices=vertices,
        faces=np.asarray(state.corners, dtype=np.int64).reshape(-1, 3),
        applied=applied,
        insertions=ext["insertions"],
        complete_faces=ext["faceCount"],
        complete_vertices=ext["vertexCount"],
        layout=layout,
    )


def _unzigzag(z: int) -> int:
    return z >> 1 if z % 2 == 0 else -((z + 1) >> 1)


def _ordered(bits: int) -> int:
    """A float's bits (as a signed 32-bit integer) in an order that follows the floats'."""
    return bits ^ 0x7FFFFFFF if bits < 0 else bits


class _State:
    """What a decoder keeps: the vertex bytes, the faces (3 corners a slot) and, for each side
    of each face (3 * slot + c, from corner c to c + 1), the side across it or -1."""

    def __init__(self, base_indices, base_vertices: bytes, stride: int, layout: dict):
        self.stride = stride
        self.vertices = bytearray(base_vertices)
        self.corners = [int(i) for i in base_indices]
        self.across = [-1] * len(self.corners)
        # Vertex fields in coding order: (offset, count, is_float).
        self.groups = [(0, 3, True)]
        if layout["normal"] is not None:
            self.groups.append((layout["normal"], 3, True))
        if layout["color"] is not None:
            self.groups.append((layout["color"], 4, False))
        if layout["uv"] is not None:
            self.groups.append((layout["uv"], 2, True))
        waiting = {}  # the base rule: at most one side waits for each way between two vertices
        for s in range(len(self.corners)):
            a, b = self.corners[s], self.corners[_next(s)]
            t = waiting.pop((b, a), None)
            if t is not None:
                self.across[s], self.across[t] = t, s
            else:
                waiting.setdefault((a, b), s)
        self.previous_first = 0

    @property
    def vertex_count(self) -> int:
        return len(self.vertices) // self.stride

    def walk(self, first: int, count: int, bits: _Bits) -> list[int]:
        """The patch: from face ``first``, one steering bit per side whose face across is not
        listed yet, until ``count`` faces."""
        order = [first]
        i = 0
        while len(order) < count:
            if i == len(order):
                raise ValueError("a record's patch walk ends early: not a stream this reads")
            for c in range(3):
                if len(order) == count:
                    break
                t = self.across[3 * order[i] + c]
                if t < 0 or t // 3 in order:
                    continue
                if bits.bit():
                    order.append(t // 3)
            i += 1
        return order

    def write(self, patch: list[int], faces: list[list[int]]) -> None:
        """The faces into the patch's slots, the rest appended; their sides paired by the
        record rule."""
        outer = []  # [a, b, side across, used]
        for p in patch:
            for c in range(3):
                s = 3 * p + c
                t = self.across[s]
                if t < 0 or t // 3 in patch:
                    continue
                outer.append([self.corners[s], self.corners[_next(s)], t, False])
                self.across[t] = -1
        sides = []
        for i, f in enumerate(faces):
            if i < len(patch):
                slot = patch[i]
            else:
                slot = len(self.corners) // 3
                self.corners.extend((0, 0, 0))
                self.across.extend((-1, -1, -1))
            for c in range(3):
                self.corners[3 * slot + c] = f[c]
                self.across[3 * slot + c] = -1
                sides.append(3 * slot + c)
        for i, s in enumerate(sides):
            if self.across[s] >= 0:
                continue
            a, b = self.corners[s], self.corners[_next(s)]
            paired = False
            for o in outer:
                if not o[3] and o[0] == a and o[1] == b:
                    o[3] = paired = True
                    self.across[s], self.across[o[2]] = o[2], s
                    break
            if paired:
                continue
            for t in sides[i + 1 :]:
                if self.across[t] < 0 and self.corners[t] == b and self.corners[_next(t)] == a:
                    self.across[s], self.across[t] = t, s
                    break

    def apply(self, stream: bytes, at: int) -> int:
        """Applies the record at ``at``; returns where the next begins (EOFError: the record is
        not whole)."""
        head, at = _varint(stream, at)
        k, listed, shape, irregular = head >> 4, (head >> 3) & 1, (head >> 1) & 3, head & 1
        added, apex_ref = 1, 0
        if irregular:
            added, at = _varint(stream, at)
            if shape:
                apex_ref, at = _varint(stream, at)
        if shape in (_CLOSED_FAN, _OPEN_FAN):
            reused = k - 2 if shape == _CLOSED_FAN else k - 1
        else:
            reused, at = _varint(stream, at)
        if reused > k:
            raise ValueError("a record replacing %d faces with %d: not a stream this reads" % (reused, k))
        count = len(self.corners) // 3
        # First the record's numbers, then its run of bits: the walk's steering, the vertices.
        if listed:
            slots = []
            for _ in range(reused):
                back, at = _varint(stream, at)
                slots.append(count - 1 - back)
        else:
            step, at = _varint(stream, at)
            first = self.previous_first + _unzigzag(step)
        refs = []  # the ring's or the faces' vertex references
        start = open_ = 0
        if shape == _OPEN_FAN:
            start, at = _varint(stream, at)
        elif shape == _LISTED_RING:
            open_, at = _varint(stream, at)
        if shape in (_LISTED_RING, 0):
            for _ in range(k + open_ if shape == _LISTED_RING else 3 * k):
                r, at = _varint(stream, at)
                refs.append(r)
        bits = _Bits(stream, at)
        if not listed:
            slots = self.walk(first, reused, bits)
        patch = [self.corners[3 * s + c] for s in slots for c in range(3)]
        before = self.vertex_count

        def vertex(ref):
            if ref < added:
                return before + ref
            if ref < added + len(patch):
                return patch[ref - added]
            return before - 1 - (ref - added - len(patch))

        if shape in (_CLOSED_FAN, _OPEN_FAN):
            # The outline: the patch's sides with no patch face across, in the patch's order.
            outline = [(patch[t], patch[_next(t)]) for t in range(len(patch))
                       if self.across[3 * slots[t // 3] + t % 3] < 0
                       or self.across[3 * slots[t // 3] + t % 3] // 3 not in slots]
            ring = [outline[start][0]]
            while len(ring) < (k if shape == _CLOSED_FAN else k + 1):
                ring.append(next(b for a, b in outline if a == ring[-1]))
            apex = vertex(apex_ref)
            n = len(ring)
            new_faces = [[apex, ring[i], ring[(i + 1) % n]] for i in range(k)]
        elif shape == _LISTED_RING:
            ring = [vertex(r) for r in refs]
            apex = vertex(apex_ref)
            n = len(ring)
            new_faces = [[apex, ring[i], ring[(i + 1) % n]] for i in range(k)]
        else:
            new_faces = [[vertex(r) for r in refs[3 * i : 3 * i + 3]] for i in range(k)]
        # The new vertices: each value its prediction plus a residual.
        rows = bytearray()
        for j in range(added):
            v = before + j
            known = []  # the older vertices of its faces, each once, in the faces' order
            for f in new_faces:
                if v in f:
                    for u in f:
                        if u < before and u not in known:
                            known.append(u)
            row = bytearray(self.stride)
            for offset, width, floats in self.groups:
                for i in range(width):
                    if floats:
                        o = offset + 4 * i
                        if known:
                            mean = sum(struct.unpack_from("<f", self.vertices, self.stride * u + o)[0] for u in known)
                            predicted = struct.pack("<f", mean / len(known))
                        elif j:
                            predicted = bytes(rows[self.stride * (j - 1) + o : self.stride * (j - 1) + o + 4])
                        else:
                            predicted = bytes(4)
                        p = _ordered(struct.unpack("<i", predicted)[0])
                        spread = max((abs(_ordered(struct.unpack_from("<i", self.vertices, self.stride * u + o)[0]) - p)
                                      for u in known), default=0)
                        m = p + _unzigzag(bits.rice(_rice_parameter(spread)))
                        struct.pack_into("<i", row, o, _ordered(m))
                    else:
                        o = offset + i
                        if known:
                            predicted = math.floor(sum(self.vertices[self.stride * u + o] for u in known) / len(known) + 0.5)
                        elif j:
                            predicted = rows[self.stride * (j - 1) + o]
                        else:
                            predicted = 0
                        spread = max((abs(self.vertices[self.stride * u + o] - predicted) for u in known), default=0)
                        row[o] = (predicted + _unzigzag(bits.rice(_rice_parameter(spread)))) & 0xFF
            rows += row
        if not listed:
            self.previous_first = first
        self.vertices += rows
        self.write(slots, new_faces)
        return bits.end()


def _next(side: int) -> int:
    return side - 2 if side % 3 == 2 else side + 1
