"""Per-face normals are not seams: every mesh of CGAL's data set and every OBJ/PLY/STL/OFF model
of assimp's test models (>= 200 faces), written as an OBJ with one normal per face (flat
shading, `f 1//1 2//1 3//1`, as CAD exporters write) and as the same OBJ without normals,
reaches the same face count through the CLI at 50 %, 10 % and 1 %; rebuilt faces of a
flat-shaded mesh carry their own normal.
    python test_flat_normals.py VRSIMPLIFY CGAL_MESHES_DIR OUT_DIR
"""
import concurrent.futures
import json
import os
import pathlib
import subprocess
import sys

import numpy as np
import trimesh

RATIOS = (0.5, 0.1, 0.01)
MAX_FACES = 100000  # larger meshes add time, not cases


def inputs(cgal):
    files = sorted(pathlib.Path(cgal).glob("*.off")) + sorted(pathlib.Path(cgal).glob("*.ply"))
    for ext in ("obj", "ply", "stl", "off"):
        files += sorted(p for p in pathlib.Path("/usr/share/assimp/models").rglob("*")
                        if p.suffix.lower() == "." + ext)
    return files


def write_obj(path, v, f, normals):
    with open(path, "w") as out:
        out.write("".join(f"v {x:.9g} {y:.9g} {z:.9g}\n" for x, y, z in v))
        if normals is None:
            out.write("".join(f"f {a} {b} {c}\n" for a, b, c in f + 1))
        else:
            out.write("".join(f"vn {x:.7g} {y:.7g} {z:.7g}\n" for x, y, z in normals))
            out.write("".join(f"f {a}//{i} {b}//{i} {c}//{i}\n"
                              for i, (a, b, c) in enumerate(f + 1, start=1)))


def run(bin_, src, dst, ratio):
    p = subprocess.run([bin_, str(src), str(dst), "--ratio", str(ratio), "--json", "--quiet"],
                       capture_output=True, text=True)
    if p.returncode != 0:
        return None
    return json.loads(p.stdout)


def case(bin_, path, out):
    try:
        mesh = trimesh.load(path, process=False, force="mesh")
    except Exception:
        return path.name, "unreadable by trimesh", []
    v, f = np.asarray(mesh.vertices, np.float64), np.asarray(mesh.faces, np.int64)
    if not (200 <= len(f) <= MAX_FACES):
        return path.name, "size", []
    stem = out / f"{path.parent.name}-{path.stem}"
    normals = np.asarray(mesh.face_normals)
    write_obj(f"{stem}-plain.obj", v, f, None)
    write_obj(f"{stem}-flat.obj", v, f, normals)
    problems = []
    for ratio in RATIOS:
        plain = run(bin_, f"{stem}-plain.obj", f"{stem}-plain-out.obj", ratio)
        flat = run(bin_, f"{stem}-flat.obj", f"{stem}-flat-out.obj", ratio)
        if plain is None or flat is None:
            problems.append(f"{ratio}: the CLI failed")
        elif (plain["output_faces"], plain["target_reached"]) != (flat["output_faces"], flat["target_reached"]):
            problems.append(f"{ratio}: {flat['output_faces']} faces with per-face normals, "
                            f"{plain['output_faces']} without")
    return path.name, "ran", problems


def main():
    bin_, cgal, out = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3])
    out.mkdir(parents=True, exist_ok=True)
    with concurrent.futures.ThreadPoolExecutor(os.cpu_count()) as pool:
        results = list(pool.map(lambda p: case(bin_, p, out), inputs(cgal)))
    ran = [r for r in results if r[1] == "ran"]
    failures = [(name, p) for name, _, problems in ran for p in problems]
    for name, p in failures:
        print(f"FAIL {name}: {p}")
    print(f"{len(ran)} meshes x {len(RATIOS)} ratios, {len(failures)} differ "
          f"({sum(r[1] == 'size' for r in results)} outside {200}..{MAX_FACES} faces, "
          f"{sum(r[1].startswith('unreadable') for r in results)} unreadable by trimesh)")
    assert len(ran) >= 90, "too few meshes ran"
    # A flat-shaded output: one normal per face, each the face's own.
    sphere = out / "sphere"
    m = trimesh.creation.icosphere(3)
    write_obj(f"{sphere}-flat.obj", m.vertices, m.faces, m.face_normals)
    report = run(bin_, f"{sphere}-flat.obj", f"{sphere}-out.obj", 0.1)
    assert report and report["target_reached"] and report["constrained_edges"] == 0, report
    got = trimesh.load(f"{sphere}-out.obj", process=False)
    lines = [l.split() for l in open(f"{sphere}-out.obj") if l.startswith(("vn ", "f "))]
    vn = np.array([[float(x) for x in l[1:]] for l in lines if l[0] == "vn"])
    corner_n = [[int(c.split("/")[2]) - 1 for c in l[1:]] for l in lines if l[0] == "f"]
    assert all(len(set(c)) == 1 for c in corner_n), "a face's corners have different normals"
    own = np.einsum("ij,ij->i", vn[[c[0] for c in corner_n]], got.face_normals)
    assert own.min() > 0.999, f"a face's normal is not its own (cos {own.min():.4f})"
    if failures:
        sys.exit(1)


if __name__ == "__main__":
    main()
