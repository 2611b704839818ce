"""A prefix of a progressive .glb as a mesh: the records whole in its first SHARE of bytes,
decoded by the reference decoder and written as a binary PLY (positions and faces); prints
the prefix's figures as one JSON line.
    python bench/progressive_prefix.py FILE.glb SHARE OUT.ply"""
import importlib.util
import json
import pathlib
import sys

import numpy as np

here = pathlib.Path(__file__).resolve().parents[1]
spec = importlib.util.spec_from_file_location(
    "progressive_file", here / "python" / "vrsimplify" / "progressive_file.py")
progressive_file = importlib.util.module_from_spec(spec)
sys.modules["progressive_file"] = progressive_file
spec.loader.exec_module(progressive_file)

path, share, out = sys.argv[1], float(sys.argv[2]), sys.argv[3]
data = pathlib.Path(path).read_bytes()
cut = int(share * len(data))
p = progressive_file.read_progressive(data[:cut])
pos = p.positions().astype("<f4")
faces = p.faces.astype("<i4")
with open(out, "wb") as f:
    f.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\n"
             "property float y\nproperty float z\nelement face %d\n"
             "property list uchar int vertex_indices\nend_header\n" % (len(pos), len(faces))).encode())
    f.write(pos.tobytes())
    rows = np.empty(len(faces), dtype=[("n", "u1"), ("v", "<i4", 3)])
    rows["n"] = 3
    rows["v"] = faces
    f.write(rows.tobytes())
print(json.dumps({"bytes": cut, "records": p.applied, "insertions": p.insertions,
                  "faces": int(len(faces)), "vertices": int(len(pos))}))
