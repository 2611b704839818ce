"""Progressive meshes: vrsimplify.progressive() records one insertion a removed vertex, and
applied in order they give back every input face in its slot; the .glb the command line writes
(--progressive) decodes, whole, to the input's faces with every attribute bit-equal, and every
prefix of the file to a valid mesh."""
import json
import shutil
import subprocess

import numpy as np
import pytest

import vrsimplify

from conftest import MESHES


def rotated(faces):
    """Each row rotated to start at its lowest entry (orientation kept)."""
    faces = np.asarray(faces)
    k = np.argmin(faces, axis=1)
    idx = (k[:, None] + np.arange(3)[None, :]) % 3
    return np.take_along_axis(faces, idx, axis=1)


def problems(faces):
    """What is wrong with a mesh's faces: a repeated vertex, a directed edge twice, an edge of
    more than two faces."""
    faces = faces[faces[:, 0] >= 0]
    if (faces[:, 0] == faces[:, 1]).any() or (faces[:, 1] == faces[:, 2]).any() or (
            faces[:, 2] == faces[:, 0]).any():
        return "a face repeats a vertex"
    directed = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    if len(np.unique(directed, axis=0)) != len(directed):
        return "a directed edge twice"
    _, counts = np.unique(np.sort(directed, axis=1), axis=0, return_counts=True)
    if counts.max() > 2:
        return "an edge of more than two faces"
    return ""


@pytest.mark.parametrize("base", [0.01, 0.1])
def test_insertions_give_back_the_input_slot_by_slot(fandisk, base):
    v, f = fandisk
    p = vrsimplify.progressive(v, f, base=base)
    assert p.report["target_reached"], p.report["stop_detail"]
    start = p.faces_after(0)
    assert (start[:, 0] >= 0).sum() == p.report["output_faces"] <= base * len(f)
    assert p.insertions == p.report["removed"] == len(np.unique(p.vertex))
    assert len(p.first) == p.insertions + 1 and p.corners.shape == (len(p.slots), 3)
    for count in np.linspace(0, p.insertions, 9).astype(int):
        now = p.faces_after(int(count))
        assert problems(now) == "", f"after {count} insertions: {problems(now)}"
        assert (now[:, 0] >= 0).sum() >= (start[:, 0] >= 0).sum()
    whole = p.faces_after(p.insertions)
    assert (rotated(whole) == rotated(f)).all(), "every input face back in its slot, same way round"
    assert (p.corners_after(p.insertions) // 3 == np.arange(len(f))[:, None]).all()


def test_bad_parameters_raise(sphere):
    v, f = sphere
    for base in (0, 1.5, float("nan")):
        with pytest.raises(ValueError):
            vrsimplify.progressive(v, f, base=base)
    p = vrsimplify.progressive(v, f, base=0.1)
    with pytest.raises(ValueError):
        p.faces_after(p.insertions + 1)


def two_chart_obj(path, n=48):
    """A bumpy sheet of two texture charts (per-corner UVs, a seam down the middle)."""
    x, y = np.meshgrid(np.arange(n + 1, dtype=np.float64), np.arange(n + 1, dtype=np.float64))
    z = 0.3 * np.sin(x * 0.7) * np.cos(y * 0.5)
    v = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)
    i = (np.arange(n)[:, None] * (n + 1) + np.arange(n)[None, :]).ravel()
    f = np.concatenate([np.stack([i, i + 1, i + n + 2], 1), np.stack([i, i + n + 2, i + n + 1], 1)])
    chart = v[f].mean(axis=1)[:, 0] >= n / 2
    with open(path, "w") as out:
        for p in v:
            out.write("v %.6f %.6f %.6f\n" % tuple(p))
        for p in v:  # chart 0's coordinates, then chart 1's (shifted)
            out.write("vt %.6f %.6f\n" % (p[0] / n / 2, p[1] / n))
        for p in v:
            out.write("vt %.6f %.6f\n" % (0.5 + p[0] / n / 2, p[1] / n))
        for face, c in zip(f, chart):
            t = face + (len(v) if c else 0)
            out.write("f %d/%d %d/%d %d/%d\n" % (face[0] + 1, t[0] + 1, face[1] + 1, t[1] + 1,
                                                 face[2] + 1, t[2] + 1))


def plain_glb_faces(path):
    """The one level of a plain .glb: its faces as triples of vertex records (bytes)."""
    from vrsimplify.progressive_file import _chunks

    doc, binary = _chunks(open(path, "rb").read())
    prim = doc["meshes"][0]["primitives"][0]
    pos = doc["accessors"][prim["attributes"]["POSITION"]]
    view = doc["bufferViews"][pos["bufferView"]]
    stride, at = view["byteStride"], view.get("byteOffset", 0)
    rows = np.frombuffer(binary[at:at + pos["count"] * stride], np.uint8).reshape(-1, stride)
    ia = doc["accessors"][prim["indices"]]
    iview = doc["bufferViews"][ia["bufferView"]]
    dtype = np.uint32 if ia["componentType"] == 5125 else np.uint16
    at = iview.get("byteOffset", 0)
    idx = np.frombuffer(binary[at:at + ia["count"] * np.dtype(dtype).itemsize], dtype)
    return as_records(rows, idx.reshape(-1, 3))


def as_records(rows, faces):
    out = []
    for t in faces:
        r = [rows[int(i)].tobytes() for i in t]
        k = min(range(3), key=lambda i: r[i])
        out.append(tuple(r[k:] + r[:k]))
    return sorted(out)


@pytest.mark.parametrize("kind", ["fandisk", "two charts"])
def test_progressive_glb_decodes_to_the_input_and_every_prefix_to_a_mesh(tmp_path, kind):
    exe = shutil.which("vrsimplify")
    src = MESHES / "fandisk.off"
    if kind == "two charts":
        src = tmp_path / "charts.obj"
        two_chart_obj(src)
    prog, full = tmp_path / "p.glb", tmp_path / "full.glb"
    run = subprocess.run([exe, str(src), str(prog), "--progressive", "--base", "0.02", "--json"],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    report = json.loads(run.stdout)
    assert report["file_bytes"] == prog.stat().st_size
    assert subprocess.run([exe, str(src), str(full), "--lods", "1"], capture_output=True).returncode == 0
    whole = vrsimplify.read_progressive(prog)
    assert whole.applied == whole.insertions
    assert len(whole.faces) == whole.complete_faces and len(whole.vertices) == whole.complete_vertices
    # Every face of the input, with every attribute of its corners bit-equal.
    assert as_records(whole.vertices, whole.faces) == plain_glb_faces(full)
    assert prog.stat().st_size < full.stat().st_size, "smaller than the full mesh alone"
    if kind == "two charts":  # the seam kept at every prefix: no face takes both charts' UVs
        for count in (0, whole.insertions // 3, whole.insertions):
            part = vrsimplify.read_progressive(prog, count)
            u = part.attribute("uv", 2, np.float32)[part.faces][:, :, 0]
            assert ((u >= 0.5).all(axis=1) | (u < 0.5).all(axis=1)).all(), count
    # Prefixes of the file: the base once its bytes are in, then more records, each a mesh.
    data = prog.read_bytes()
    first = report["base_bytes"]
    assert first < 0.1 * len(data), report
    base = vrsimplify.read_progressive(data[:first])
    assert base.applied == 0 and len(base.faces) == report["base_faces"]
    applied = 0
    for share in (0.25, 0.6, 1.0):
        part = vrsimplify.read_progressive(data[:first + int(share * (len(data) - first))])
        assert part.applied >= applied
        applied = part.applied
        assert problems(part.faces) == "", f"{share}: {problems(part.faces)}"
        assert len(part.faces) >= len(base.faces)
    assert applied == whole.insertions
    with pytest.raises(ValueError):
        vrsimplify.read_progressive(full)
    # A file of another coding (version 2: residuals as varints) is refused, not misread.
    older = data.replace(b'"version":3', b'"version":2', 1)
    assert older != data
    with pytest.raises(ValueError, match="version 2"):
        vrsimplify.read_progressive(older)


def test_cli_refuses_what_a_progressive_file_cannot_hold(tmp_path):
    exe = shutil.which("vrsimplify")
    for args in (["--progressive", "--lods", "3"], ["--progressive", "--compress"],
                 ["--progressive", "--ratio", "0.1"], ["--base", "0.1"], ["--progressive", "--base", "0"]):
        out = tmp_path / "x.glb"
        r = subprocess.run([exe, str(MESHES / "fandisk.off"), str(out), *args], capture_output=True, text=True)
        assert r.returncode == 2 and r.stderr.count("\n") == 1, (args, r.stderr)
        assert not out.exists()
    r = subprocess.run([exe, str(MESHES / "fandisk.off"), str(tmp_path / "x.ply"), "--progressive"],
                       capture_output=True, text=True)
    assert r.returncode == 2 and ".glb" in r.stderr
