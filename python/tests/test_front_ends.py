"""One input, one output: the command line, the numpy API (float64 arrays read from the file in
its order, any integer dtype) and a tiled run of one tile give the same vertices and faces, in
the same order, for the same mesh and options; pymeshlab the same vertices in the same order and
the same faces (each with its corners in the same order), listed in MeshLab's order: MeshLab
keeps each face the run leaves in its slot, with its own data, and adds the new ones after
(docs/usage.md, "One input, one output"). On the shipped meshes and public ones (CGAL's data set),
written as double- and float-precision PLY files."""
import os
import pathlib
import subprocess
import warnings

import numpy as np
import pytest

import vrsimplify
from conftest import MESHES

CGAL = pathlib.Path(__file__).resolve().parents[2] / "third_party" / "cgal-data" / "data" / "meshes"
SHIPPED = sorted(MESHES.glob("*.off"))
PUBLIC = [CGAL / n for n in ("bunny00.off", "armadillo.off", "cow.off", "lion-head.off",
                             "turbine.off", "helmet.off")]


def read_off(path):
    tokens = open(path).read().split()
    at = 1 if tokens[0] == "OFF" else 0
    nv, nf = int(tokens[at]), int(tokens[at + 1])
    at += 3
    v = np.array(tokens[at:at + 3 * nv], dtype=np.float64).reshape(-1, 3)
    at += 3 * nv
    f = np.array([tokens[at + 4 * i + 1:at + 4 * i + 4] for i in range(nf)], dtype=np.int64)
    assert all(tokens[at + 4 * i] == "3" for i in range(nf)), "triangles only"
    return v, f


def write_ply(path, v, f, dtype):
    kind = {np.float64: "double", np.float32: "float"}[dtype]
    with open(path, "wb") as out:
        out.write(("ply\nformat binary_little_endian 1.0\n"
                   f"element vertex {len(v)}\nproperty {kind} x\nproperty {kind} y\nproperty {kind} z\n"
                   f"element face {len(f)}\nproperty list uchar int vertex_indices\nend_header\n").encode())
        out.write(np.asarray(v, dtype=np.dtype(dtype).newbyteorder("<")).tobytes())
        rec = np.zeros(len(f), dtype=[("n", "u1"), ("i", "<i4", (3,))])
        rec["n"], rec["i"] = 3, f
        out.write(rec.tobytes())


def read_ply(path):
    """A binary PLY as the command line writes it: its x, y, z (float or double) and faces."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    head = data[:end].decode().splitlines()
    counts = {l.split()[1]: int(l.split()[2]) for l in head if l.startswith("element")}
    props, element = [], None
    for line in head:
        if line.startswith("element"):
            element = line.split()[1]
        elif line.startswith("property") and element == "vertex":
            props.append((line.split()[2], {"double": "<f8", "float": "<f4", "uchar": "u1",
                                            "int": "<i4", "uint": "<u4"}[line.split()[1]]))
    vertex = np.frombuffer(data, dtype=props, count=counts["vertex"], offset=end)
    at = end + vertex.nbytes
    faces = np.frombuffer(data, dtype=[("n", "u1"), ("i", "<i4", (3,))], count=counts["face"], offset=at)
    assert (faces["n"] == 3).all()
    return np.stack([vertex["x"], vertex["y"], vertex["z"]], axis=1).astype(np.float64), faces["i"].astype(np.int64)


def meshes():
    out = [pytest.param(p, id=p.stem) for p in SHIPPED]
    out += [pytest.param(p, id=p.stem, marks=pytest.mark.skipif(not p.exists(), reason="CGAL's data set"))
            for p in PUBLIC]
    return out


def cli(src, dst, *extra):
    p = subprocess.run(["vrsimplify", str(src), str(dst), "--ratio", "0.1", "--threads", "1", *extra],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return read_ply(dst)


@pytest.mark.parametrize("path", meshes())
@pytest.mark.parametrize("precision", [np.float64, np.float32])
def test_every_front_end_gives_the_same_output(path, precision, tmp_path):
    v, f = read_off(path)
    v = v.astype(precision)
    src = tmp_path / "in.ply"
    write_ply(src, v, f, precision)
    out_v, out_f = cli(src, tmp_path / "cli.ply")
    # The numpy API on the file's own arrays, whatever the faces' integer dtype.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vrsimplify.TargetNotReachedWarning)
        for faces in (f, f.astype(np.int32), f.astype(np.uint32)):
            r = vrsimplify.simplify(v, faces, ratio=0.1, threads=1)
            assert np.array_equal(r.vertices.astype(np.float64), out_v), "numpy API: vertices"
            assert np.array_equal(r.faces, out_f), "numpy API: faces"
    # A tiled run whose budget holds the whole mesh: one tile, the same run.
    tiled = tmp_path / "tiled.ply"
    report = vrsimplify.tiled.simplify(src, tiled, ratio=0.1, memory="4G", workers=1)
    assert len(report["levels"]) == 1 and report["levels"][0]["tiles"] == 1, report
    t_v, t_f = read_ply(tiled)
    assert np.array_equal(t_v, out_v) and np.array_equal(t_f, out_f), "tiled run of one tile"


@pytest.mark.parametrize("path", meshes())
def test_pymeshlab_gives_the_command_lines_output(path, tmp_path):
    if not os.environ.get("VRS_REQUIRE_PYMESHLAB"):
        pytest.importorskip("pymeshlab")
    import pymeshlab
    import vrsimplify.pymeshlab  # noqa: F401
    v, f = read_off(path)
    src = tmp_path / "in.ply"
    write_ply(src, v, f, np.float64)
    out_v, out_f = cli(src, tmp_path / "cli.ply")
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(src))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vrsimplify.TargetNotReachedWarning)
        ms.meshing_decimation_vertex_removal(targetperc=0.1)
    m = ms.current_mesh()
    assert np.array_equal(m.vertex_matrix(), out_v), "pymeshlab: vertices"
    faces = m.face_matrix()
    assert faces.shape == out_f.shape
    # Each face as its corners from the least on: the same corners in the same cyclic order.
    canon = lambda t: np.roll(t, -int(np.argmin(t)), axis=0).tolist()
    assert sorted(map(canon, faces)) == sorted(map(canon, out_f)), "pymeshlab: faces"
