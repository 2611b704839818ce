#!/usr/bin/env python3
"""Each level of a vrsimplify .glb as its own binary PLY (positions and triangles), to measure
it with vrs_bench --compare: what the file holds, not what the run meant to write.

    glb_levels.py FILE.glb OUT_PREFIX   -> OUT_PREFIX0.ply (finest), OUT_PREFIX1.ply, ...
"""
import json
import struct
import sys

import numpy as np


def levels(path):
    data = open(path, "rb").read()
    json_bytes = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + json_bytes])
    start = 20 + json_bytes + 8
    top = doc["scenes"][doc.get("scene", 0)]["nodes"][0]
    nodes = [top] + doc["nodes"][top].get("extensions", {}).get("MSFT_lod", {}).get("ids", [])
    for n in nodes:
        prim = doc["meshes"][doc["nodes"][n]["mesh"]]["primitives"][0]
        pa = doc["accessors"][prim["attributes"]["POSITION"]]
        pv = doc["bufferViews"][pa["bufferView"]]
        stride = pv.get("byteStride", 12)
        raw = np.frombuffer(data, np.uint8, pa["count"] * stride, start + pv.get("byteOffset", 0))
        pos = raw.reshape(-1, stride)[:, :12].copy().view(np.float32).reshape(-1, 3)
        ia = doc["accessors"][prim["indices"]]
        iv = doc["bufferViews"][ia["bufferView"]]
        dtype = np.uint32 if ia["componentType"] == 5125 else np.uint16
        idx = np.frombuffer(data, dtype, ia["count"], start + iv.get("byteOffset", 0)).reshape(-1, 3)
        yield pos, idx


def write_ply(path, pos, faces):
    with open(path, "wb") as f:
        f.write(f"ply\nformat binary_little_endian 1.0\nelement vertex {len(pos)}\n"
                "property float x\nproperty float y\nproperty float z\n"
                f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n".encode())
        f.write(pos.astype("<f4").tobytes())
        rec = np.zeros(len(faces), dtype=[("n", "u1"), ("i", "<i4", 3)])
        rec["n"] = 3
        rec["i"] = faces
        f.write(rec.tobytes())


if __name__ == "__main__":
    for k, (pos, idx) in enumerate(levels(sys.argv[1])):
        write_ply(f"{sys.argv[2]}{k}.ply", pos, idx.astype(np.int64))
