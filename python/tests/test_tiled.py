"""Tiled runs through the package: a ~1.3 M-face closed mesh cut into tiles (a small memory
budget forces them), on local processes and on a real Dask cluster (a LocalCluster of two
worker processes): the same output byte for byte, watertight, every vertex an input vertex,
the target met; a worker killed mid-run changes nothing; Ctrl-C leaves nothing; bad input is
a clear error that leaves nothing behind."""
import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest
import trimesh

import vrsimplify.tiled
from conftest import edge_face_counts, split_sphere

PLY_FACE = np.dtype([("n", "u1"), ("v", "<i4", (3,))])


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().split("\n")
    nv = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    nf = int(next(l for l in header if l.startswith("element face")).split()[2])
    v = np.frombuffer(data, "<f4", 3 * nv, end).reshape(nv, 3)
    return v, np.frombuffer(data, PLY_FACE, nf, end + 12 * nv)["v"].astype(np.int64)


@pytest.fixture(scope="module")
def big(tmp_path_factory):
    m = trimesh.creation.icosphere(subdivisions=8)  # 1 310 720 faces, closed
    # Bumps, so that the error decides where vertices go.
    v = m.vertices * (1 + 0.05 * np.sin(7 * m.vertices[:, :1]) * np.cos(5 * m.vertices[:, 1:2]))
    path = tmp_path_factory.mktemp("tiled") / "sphere.ply"
    v = v.astype(np.float32)  # what the tiled run reads (it keeps float positions)
    trimesh.Trimesh(v, m.faces, process=False).export(path)  # binary PLY
    return path, v, np.asarray(m.faces)


def check_output(path, v_in, faces_in, ratio):
    v, f = read_ply(path)
    target = int(ratio * len(faces_in))
    assert len(f) <= target * 1.005 + 2
    inputs = {tuple(p) for p in v_in.tolist()}
    assert all(tuple(p) in inputs for p in v.tolist())  # input vertices, bit for bit
    counts = edge_face_counts(f)
    assert set(counts.values()) == {2}  # watertight, manifold: no crack at any tile border
    directed = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    assert len(np.unique(directed, axis=0)) == len(directed)  # orientation kept


def test_local_processes_and_dask_give_the_same_output(big, tmp_path):
    distributed = pytest.importorskip("distributed")
    src, v, f = big
    local = tmp_path / "local.ply"
    r = vrsimplify.tiled.simplify(src, local, ratio=0.1, memory="64M", workers=2)
    assert len(r["levels"]) >= 2 and r["levels"][0]["tiles"] > 4
    check_output(local, v, f, 0.1)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        on_dask = tmp_path / "dask.ply"
        r2 = vrsimplify.tiled.simplify(src, on_dask, ratio=0.1, memory="64M", client=client)
        # The work directory as an fsspec URL: tiles fetched and returned by the workers.
        by_url = tmp_path / "url.ply"
        shared = tmp_path / "shared"
        r3 = vrsimplify.tiled.simplify(src, by_url, ratio=0.1, memory="64M", client=client,
                                       workdir=shared.as_uri())
    assert r2["output_faces"] == r["output_faces"] == r3["output_faces"]
    assert local.read_bytes() == on_dask.read_bytes() == by_url.read_bytes()
    assert not list(tmp_path.glob("vrsimplify-tiles-*"))  # the work directories are cleaned up
    assert not list(shared.iterdir())


def test_a_worker_killed_while_it_runs_tiles_changes_nothing(big, tmp_path):
    """A worker process killed (SIGKILL) while it holds tile tasks: Dask gives them to the other
    worker (the nanny restarts the dead one), the tiles it may have half written are written
    again whole, and the output is the local run's, byte for byte."""
    distributed = pytest.importorskip("distributed")
    src, v, f = big
    local = tmp_path / "local.ply"
    vrsimplify.tiled.simplify(src, local, ratio=0.1, memory="64M", workers=2)
    out, result = tmp_path / "dask.ply", {}
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        pids = client.run(os.getpid)  # worker address -> its process
        run = threading.Thread(target=lambda: result.update(vrsimplify.tiled.simplify(
            src, out, ratio=0.1, memory="64M", client=client, workdir=tmp_path)))
        run.start()
        victim, deadline = None, time.monotonic() + 120
        while victim is None and run.is_alive() and time.monotonic() < deadline:
            busy = [a for a, keys in client.processing().items()
                    if any("_run_tile" in str(k) for k in keys)]
            victim = busy[0] if busy else None
            time.sleep(0.005)
        assert victim, "no worker was seen running a tile"
        os.kill(pids[victim], signal.SIGKILL)
        run.join(300)
        assert not run.is_alive()
    assert result["output_faces"] <= 0.1 * len(f) * 1.005 + 2
    assert out.read_bytes() == local.read_bytes()
    assert not list(tmp_path.glob("vrsimplify-tiles-*"))


def test_a_named_work_directory_keeps_what_it_held(big, tmp_path):
    src, v, f = big
    scratch = tmp_path / "scratch"
    scratch.mkdir()
    (scratch / "yours.txt").write_text("keep me")
    r = vrsimplify.tiled.simplify(src, tmp_path / "o.ply", ratio=0.1, memory="64M", workers=2,
                                  workdir=scratch)
    assert r["workdir"].startswith(str(scratch / "vrsimplify-tiles-"))
    assert [p.name for p in scratch.iterdir()] == ["yours.txt"]
    assert (scratch / "yours.txt").read_text() == "keep me"
    with pytest.raises(ValueError, match="URL work directory"):
        vrsimplify.tiled.simplify(src, tmp_path / "o.ply", ratio=0.1, workdir="s3://bucket/x")


def test_one_worker_or_two_the_same_output(big, tmp_path):
    src, v, f = big
    one, two = tmp_path / "one.ply", tmp_path / "two.ply"
    r1 = vrsimplify.tiled.simplify(src, one, ratio=0.01, memory="64M", workers=1)
    r2 = vrsimplify.tiled.simplify(src, two, ratio=0.01, memory="64M", workers=0)  # the cores
    assert r1["output_faces"] == r2["output_faces"] and r1["target_reached"] in (True, False)
    assert r1["stop_reason"] == ("target_reached" if r1["target_reached"] else "no_candidates")
    check_output(one, v, f, 0.01)
    assert one.read_bytes() == two.read_bytes()


def test_ctrl_c_stops_the_workers_and_leaves_nothing(big, tmp_path):
    """Ctrl-C (SIGINT to the Python process alone, while its local workers run tiles) raises
    KeyboardInterrupt once the workers are killed and reaped: no worker left running, no work
    directory, no output."""
    src, _, _ = big
    out = tmp_path / "out.ply"
    code = ("import signal, sys, vrsimplify.tiled\n"
            "signal.signal(signal.SIGINT, signal.default_int_handler)\n"  # as in a terminal
            "vrsimplify.tiled.simplify(sys.argv[1], sys.argv[2], ratio=0.01, memory='64M', workers=2)\n")
    proc = subprocess.Popen([sys.executable, "-c", code, str(src), str(out)],
                            stderr=subprocess.PIPE, text=True)
    workers = []
    deadline = time.monotonic() + 120
    while len(workers) < 2 and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
        try:
            workers = open(f"/proc/{proc.pid}/task/{proc.pid}/children").read().split()
        except OSError:
            pass
    assert len(workers) == 2, "the workers never ran"
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode != 0 and "KeyboardInterrupt" in err, err
    for pid in workers:
        assert not os.path.exists(f"/proc/{pid}"), f"worker {pid} outlived the run"
    assert not out.exists() and not list(tmp_path.glob("vrsimplify-tiles-*"))
    assert not list(tmp_path.glob("*.tmp.*"))


def test_bad_input_is_a_clear_error_and_leaves_nothing(big, tmp_path):
    src, _, _ = big
    data = src.read_bytes()
    cases = {"truncated.ply": data[: len(data) // 2],
             "index.obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n",
             "garbage.ply": b"ply\nformat ascii 1.0\nelement vertex x\nend_header\n",
             "empty.obj": b""}
    messages = {"truncated.ply": "truncated", "index.obj": "out of range",
                "garbage.ply": "bad PLY element", "empty.obj": "no faces"}
    for name, content in cases.items():
        path = tmp_path / name
        path.write_bytes(content)
        out = tmp_path / f"out-{name}"  # the input's format: what a tiled run writes
        with pytest.raises(ValueError, match=messages[name]):
            vrsimplify.tiled.simplify(path, out, ratio=0.1, memory="64M")
        assert not out.exists() and not list(tmp_path.glob("vrsimplify-tiles-*"))
        assert not list(tmp_path.glob("*.tmp.*"))
    blocked = tmp_path / "file"
    blocked.write_text("not a folder")
    with pytest.raises(ValueError, match="cannot make|cannot write"):
        vrsimplify.tiled.simplify(src, tmp_path / "o.ply", ratio=0.1, memory="64M",
                                  workdir=str(blocked / "sub"))
    with pytest.raises(ValueError, match="memory"):
        vrsimplify.tiled.simplify(src, tmp_path / "o.ply", ratio=0.1, memory="lots")
    # A tiled run writes the input's own format (every attribute passes untouched): another is
    # refused before any work.
    for name in ("o.off", "o.stl", "o.obj"):
        with pytest.raises(ValueError, match=r"name the output \.ply"):
            vrsimplify.tiled.simplify(src, tmp_path / name, ratio=0.1, memory="64M")
        assert not (tmp_path / name).exists() and not list(tmp_path.glob("vrsimplify-tiles-*"))


def test_split_vertices_are_welded_in_the_tiles_as_in_core(tmp_path):
    # A sphere whose upper faces hold their own copies of the equator's vertices (positions
    # only): welded by default (as the in-core run of such a file), so the equator goes with
    # the rest and the output closes by position; "keep" leaves the copies apart, as borders.
    m = trimesh.creation.icosphere(subdivisions=5)
    v, f, seam, _ = split_sphere((m.vertices.astype(np.float32), np.asarray(m.faces)))
    src = tmp_path / "split.ply"
    trimesh.Trimesh(v, f, process=False).export(src)
    equator = {tuple(p) for p in v[-seam:].tolist()}

    def run(name, **kw):
        out = tmp_path / name
        r = vrsimplify.tiled.simplify(src, out, ratio=0.05, memory="1M", workers=2, **kw)
        assert len(r["levels"]) > 1  # in tiles, not one in-core run
        vo, fo = read_ply(out)
        _, by_position = np.unique(vo, axis=0, return_inverse=True)
        counts = edge_face_counts(by_position.reshape(-1)[fo])
        kept = {tuple(p) for p in vo.tolist()} & equator
        return r, set(counts.values()), len(kept)

    r, closed, kept = run("welded.ply")
    assert r["target_reached"] and closed == {2} and kept < len(equator) / 2
    _, closed, kept = run("kept.ply", split_vertices="keep")
    assert closed == {2} and kept == len(equator)
    with pytest.raises(ValueError, match="split_vertices must be seam, weld or keep"):
        vrsimplify.tiled.simplify(src, tmp_path / "never.ply", ratio=0.05, memory="1M",
                                  split_vertices="glue")
    assert not (tmp_path / "never.ply").exists()


def textured_obj(path):
    """An OBJ with everything a scan or a photogrammetry mesh carries: vertex colors on the v
    lines, a normal per vertex, texture charts (one vt per vertex and chart, its value naming
    both) and two materials. Returns the input's corners as (v line, vt line, vn line,
    material) and its v lines."""
    m = trimesh.creation.icosphere(subdivisions=5)  # 20 480 faces
    v, f = np.asarray(m.vertices), np.asarray(m.faces)
    centroid = v[f].mean(axis=1)
    chart = (centroid[:, 0] > 0) * 2 + (centroid[:, 1] > 0)
    lines = ["mtllib scan.mtl"]
    vlines = [f"v {x:.9g} {y:.9g} {z:.9g} {i % 7 / 7:.4f} 0.5 {i % 3 / 3:.4f}"
              for i, (x, y, z) in enumerate(v)]
    vnlines = ["vn %.6f %.6f %.6f" % tuple(p) for p in v]
    lines += vlines + vnlines
    vt, corners = {}, set()
    for t, face in enumerate(f):
        for c in face:
            if (c, chart[t]) not in vt:
                vt[(c, chart[t])] = len(vt) + 1
                lines.append(f"vt {c / len(v):.9g} {chart[t]}")
    vtlines = {i: f"vt {c / len(v):.9g} {ch}" for (c, ch), i in vt.items()}
    for mat in (0, 1):
        lines.append(f"usemtl side{mat}")
        for t, face in enumerate(f):
            if chart[t] // 2 != mat:
                continue
            lines.append("f " + " ".join(f"{c + 1}/{vt[(c, chart[t])]}/{c + 1}" for c in face))
            corners |= {(vlines[c], vtlines[vt[(c, chart[t])]], vnlines[c], f"side{mat}")
                        for c in face}
    path.write_text("\n".join(lines) + "\n")
    (path.parent / "scan.mtl").write_text("newmtl side0\nKd 1 0 0\nnewmtl side1\nKd 0 0 1\n")
    return corners, set(vlines), len(f)


def obj_corners(path):
    v, vt, vn, corners, material = [], [], [], [], None
    for line in path.read_text().splitlines():
        word = line.split(" ", 1)[0]
        if word == "v":
            v.append(line)
        elif word == "vt":
            vt.append(line)
        elif word == "vn":
            vn.append(line)
        elif word == "usemtl":
            material = line.split(" ", 1)[1]
        elif word == "f":
            for corner in line.split()[1:]:
                a, b, c = (int(i) - 1 for i in corner.split("/"))
                corners.append((v[a], vt[b], vn[c], material))
    return corners, v


def test_tiled_runs_keep_every_attribute_locally_and_on_dask(tmp_path):
    """Vertex colors, normals, texture charts and materials through tiles, on local processes
    and on a real Dask cluster: every output vertex is an input v line as written, every output
    corner an input corner of its chart and material, the same bytes either way."""
    distributed = pytest.importorskip("distributed")
    src = tmp_path / "in" / "scan.obj"
    src.parent.mkdir()
    corners, vlines, faces = textured_obj(src)
    local = tmp_path / "local.obj"
    r = vrsimplify.tiled.simplify(src, local, ratio=0.1, memory="1M", workers=2)
    assert r["levels"][0]["tiles"] > 4 and r["output_faces"] <= 0.1 * faces * 1.005 + 2
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        on_dask = tmp_path / "dask.obj"
        vrsimplify.tiled.simplify(src, on_dask, ratio=0.1, memory="1M", client=client)
    assert local.read_bytes() == on_dask.read_bytes()
    out_corners, out_v = obj_corners(local)
    assert set(out_v) <= vlines
    assert len(out_corners) == 3 * r["output_faces"]
    assert [c for c in out_corners if c not in corners] == []
    assert "mtllib in/scan.mtl" in local.read_text()  # named from the output's folder


def test_untouched_quads_come_back_whole_as_in_core(tmp_path):
    """A tiled run of a quad mesh writes the quads it left untouched whole, each one an input
    quad, corners in order (in core the same rule: test_polygons)."""
    n = 90
    x, y = np.meshgrid(np.arange(n + 1.0), np.arange(n + 1.0))
    v = np.stack([x.ravel(), y.ravel(), 2 * np.sin(x / 5).ravel() * np.cos(y / 7).ravel()], axis=1)
    i = (np.arange(n)[None, :] + (n + 1) * np.arange(n)[:, None]).ravel()
    quads = [(a, a + 1, a + n + 2, a + n + 1) for a in i]
    src, dst = tmp_path / "quads.obj", tmp_path / "out.obj"
    src.write_text("".join("v %.9g %.9g %.9g\n" % tuple(p) for p in v) +
                   "".join("f %d %d %d %d\n" % tuple(c + 1 for c in q) for q in quads))
    r = vrsimplify.tiled.simplify(src, dst, ratio=0.5, memory="1M")
    assert len(r["levels"]) > 1 and r["target_reached"]
    lines = [line.split() for line in dst.read_text().splitlines() if line.startswith("v ")]
    out_v = [tuple(float(c) for c in w[1:4]) for w in lines]
    faces = [[int(c) - 1 for c in line.split()[1:]] for line in dst.read_text().splitlines()
             if line.startswith("f ")]
    assert sum(len(f) - 2 for f in faces) == r["output_faces"]
    written = [tuple(float(c) for c in line.split()[1:4])
               for line in src.read_text().splitlines() if line.startswith("v ")]
    key = {p: k for k, p in enumerate(written)}  # the output copies the input's v lines
    def cyc(f):
        k = f.index(min(f))
        return tuple(f[k:] + f[:k])
    inputs = {cyc(list(q)) for q in quads}
    kept = [cyc([key[out_v[c]] for c in f]) for f in faces if len(f) == 4]
    assert len(kept) > 100 and all(q in inputs for q in kept)
