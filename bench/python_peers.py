#!/usr/bin/env python3
"""What a Python user pip-installs, beside vrsimplify's numpy API, on the whole data set.

usage: python_peers.py VRS_BENCH QUALITY_CSV OUT_CSV [--samples S] FILE...

Each mesh is read once as every method of bench/ reads it (`vrs_bench --convert`), handed to
each library as numpy arrays at the face targets of bench/quality.csv (50 / 10 / 1 %), called
as its documentation shows with the target as the only setting (meshoptimizer: target_error 1,
so the count decides, as in the C++ benchmark; it has no other way to reach a count), one
thread. Per run: faces reached, seconds (the call alone), vertices not among the input's
(moved), edges with more than two faces the input did not have (new non-manifold edges), and
the symmetric surface error measured by `vrs_bench --compare` with the same samples as the
quality benchmark, whose QECD row on the same mesh and target is the yardstick.
"""
import csv
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np

import vrsimplify

PLY_VERTEX = np.dtype("<f4")
PLY_FACE = np.dtype([("n", "u1"), ("v", "<i4", (3,))])


def read_ply(path):
    """The binary PLY `vrs_bench --convert` writes: float xyz, then (3, i, j, k) records."""
    data = pathlib.Path(path).read_bytes()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().split("\n")
    nv = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    nf = int(next(l for l in header if l.startswith("element face")).split()[2])
    v = np.frombuffer(data, PLY_VERTEX, 3 * nv, end).reshape(nv, 3)
    f = np.frombuffer(data, PLY_FACE, nf, end + 12 * nv)["v"]
    return v, f.astype(np.int64)


def write_ply(path, v, f):
    v = np.ascontiguousarray(v, dtype="<f4")
    faces = np.zeros(len(f), PLY_FACE)
    faces["n"], faces["v"] = 3, f
    with open(path, "wb") as out:
        out.write(f"ply\nformat binary_little_endian 1.0\nelement vertex {len(v)}\n"
                  "property float x\nproperty float y\nproperty float z\n"
                  f"element face {len(f)}\nproperty list uchar int vertex_indices\n"
                  "end_header\n".encode())
        out.write(v.tobytes())
        out.write(faces.tobytes())


# Each: (vertices float32, faces int64, target faces) -> (vertices, faces).
def run_ours(v, f, target):
    r = vrsimplify.simplify(v, f, faces=target, threads=1)
    return r.vertices, r.faces


def run_ours_boundary(v, f, target):  # open meshes' borders simplified too, as the others do
    r = vrsimplify.simplify(v, f, faces=target, threads=1, simplify_boundary=True)
    return r.vertices, r.faces


def run_fast_simplification(v, f, target):
    import fast_simplification
    return fast_simplification.simplify(v, f, target_reduction=1.0 - target / len(f))


def run_pyfqmr(v, f, target):
    import pyfqmr
    s = pyfqmr.Simplify()
    s.setMesh(v, f)
    s.simplify_mesh(target_count=target, verbose=False)
    out_v, out_f, _ = s.getMesh()
    return out_v, out_f


def run_meshoptimizer(v, f, target):
    import meshoptimizer
    indices = np.ascontiguousarray(f.reshape(-1), dtype=np.uint32)
    dest = np.zeros_like(indices)
    n = meshoptimizer.simplify(dest, indices, np.ascontiguousarray(v, np.float32),
                               target_index_count=3 * target, target_error=1.0)
    out_f = dest[:n].reshape(-1, 3).astype(np.int64)
    used, out_f = np.unique(out_f, return_inverse=True)  # drop the vertices no face uses
    return v[used], out_f.reshape(-1, 3)


def run_open3d(v, f, target):
    import open3d as o3d
    m = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(v.astype(np.float64)),
                                  o3d.utility.Vector3iVector(f.astype(np.int32)))
    out = m.simplify_quadric_decimation(target_number_of_triangles=target)
    return np.asarray(out.vertices), np.asarray(out.triangles)


METHODS = {
    "vrsimplify": run_ours,
    "vrsimplify-boundary": run_ours_boundary,
    "fast-simplification": run_fast_simplification,
    "pyfqmr": run_pyfqmr,
    "meshoptimizer": run_meshoptimizer,
    "open3d": run_open3d,
}


def nonmanifold_edges(v, f):
    """Edges with more than two faces, as pairs of vertex positions (method-independent)."""
    e = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
    keys, counts = np.unique(e, axis=0, return_counts=True)
    bad = keys[counts > 2]
    p = np.asarray(v, np.float32)
    return {tuple(sorted((tuple(p[a]), tuple(p[b])))) for a, b in bad}


def main():
    args = sys.argv[1:]
    bench, quality, out_csv = args[:3]
    samples = "30000"
    files = args[3:]
    if files[:1] == ["--samples"]:
        samples, files = files[1], files[2:]
    targets = {}
    with open(quality) as q:
        for row in csv.DictReader(q):
            # The input's face count too: CGAL holds pig.off and pig.stl, two meshes.
            if row["method"] == "qecd":
                targets[(row["set"], row["mesh"], row["input_faces"], row["ratio"])] = row
    work = pathlib.Path(tempfile.mkdtemp())
    fields = ["set", "mesh", "input_faces", "ratio", "target_faces", "method", "output_faces",
              "seconds", "moved_vertices", "new_nonmanifold_edges", "error_max", "error_mean",
              "qecd_error_max", "qecd_error_mean", "note"]
    with open(out_csv, "w", newline="") as out:
        writer = csv.DictWriter(out, fields)
        writer.writeheader()
        for path in files:
            set_name = "assimp" if path.startswith("/usr/share/assimp/") else "cgal"
            name = pathlib.Path(path).stem
            src = work / "in.ply"
            if subprocess.run([bench, "--convert", path, str(src)], capture_output=True).returncode:
                continue
            v, f = read_ply(src)
            rows = [k for k in targets if k[:3] == (set_name, name, str(len(f)))]
            if not rows:
                continue  # not in the quality benchmark (unreadable, or under 200 faces)
            inputs = {tuple(p) for p in v.tolist()}
            before = nonmanifold_edges(v, f)
            print(f"== {set_name} {name} ({len(f)} faces)", file=sys.stderr, flush=True)
            for key in sorted(rows, key=lambda k: -float(k[3])):
                q = targets[key]
                target = int(q["target_faces"])
                for method, run in METHODS.items():
                    row = {"set": set_name, "mesh": name, "input_faces": len(f), "ratio": key[3],
                           "target_faces": target, "method": method,
                           "qecd_error_max": q["error_max"], "qecd_error_mean": q["error_mean"],
                           "note": ""}
                    try:
                        t0 = time.perf_counter()
                        ov, of = run(v, f, target)
                        row["seconds"] = f"{time.perf_counter() - t0:.6f}"
                    except Exception as e:  # a library that refuses the mesh: said, not hidden
                        row["note"] = f"failed: {type(e).__name__}: {e}"[:200].replace("\n", " ")
                        writer.writerow(row)
                        continue
                    ov, of = np.asarray(ov), np.asarray(of, np.int64).reshape(-1, 3)
                    row["output_faces"] = len(of)
                    row["moved_vertices"] = sum(tuple(p) not in inputs
                                                for p in np.asarray(ov, np.float32).tolist())
                    row["new_nonmanifold_edges"] = len(nonmanifold_edges(ov, of) - before)
                    dst = work / "out.ply"
                    write_ply(dst, ov, of)
                    e = subprocess.run([bench, "--compare", str(src), str(dst), "--samples",
                                        samples], capture_output=True, text=True)
                    if e.returncode == 0 and len(of):
                        row["error_max"], row["error_mean"] = e.stdout.split()[:2]
                    else:
                        row["note"] = "no error measured (empty output)"
                    writer.writerow(row)
                out.flush()


if __name__ == "__main__":
    main()
