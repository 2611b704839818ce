"""The trimesh helper carries vertex colors, UVs, per-vertex attributes and face colors."""
import numpy as np
import trimesh

import vrsimplify.trimesh


def test_vertex_colors_and_attributes_follow(sphere):
    v, f = sphere
    colors = (np.arange(len(v) * 4) % 251).reshape(-1, 4).astype(np.uint8)
    mesh = trimesh.Trimesh(v, f, vertex_colors=colors, process=False)
    mesh.vertex_attributes["quality"] = np.arange(len(v), dtype=np.float64)
    out = vrsimplify.trimesh.simplify_trimesh(mesh, ratio=0.1)
    vmap = out.metadata["vrsimplify"]["vertex_map"]
    assert len(out.faces) <= 0.1 * len(f) + 1
    assert np.array_equal(out.visual.vertex_colors, colors[vmap])
    assert np.array_equal(out.vertex_attributes["quality"], vmap.astype(np.float64))
    assert np.array_equal(out.vertices, v[vmap])
    assert np.array_equal(mesh.vertices, v)  # the input mesh is untouched


def test_uvs_keep_their_values_and_material(sphere):
    v, f = sphere
    uv = np.c_[np.arctan2(v[:, 1], v[:, 0]), v[:, 2]]
    material = trimesh.visual.material.SimpleMaterial(diffuse=[200, 10, 10, 255])
    mesh = trimesh.Trimesh(v, f, visual=trimesh.visual.TextureVisuals(uv=uv, material=material),
                           process=False)
    out = vrsimplify.trimesh.simplify_trimesh(mesh, ratio=0.2)
    vmap = out.metadata["vrsimplify"]["vertex_map"]
    assert np.array_equal(out.visual.uv, uv[vmap])
    assert out.visual.material is material


def test_face_colors_come_from_the_faces_they_replace(sphere):
    v, f = sphere
    face_colors = np.zeros((len(f), 4), np.uint8)
    face_colors[:, 3] = 255
    face_colors[v[f].mean(axis=1)[:, 2] > 0, 0] = 255  # red top, black bottom
    mesh = trimesh.Trimesh(v, f, face_colors=face_colors, process=False)
    out = vrsimplify.trimesh.simplify_trimesh(mesh, ratio=0.2)
    top = out.vertices[out.faces].mean(axis=1)[:, 2]
    red = out.visual.face_colors[:, 0] == 255
    assert red[top > 0.2].all() and not red[top < -0.2].any()


def test_example_runs(tmp_path):
    import pathlib
    import subprocess
    import sys
    example = pathlib.Path(__file__).resolve().parents[1] / "examples" / "trimesh_example.py"
    out = tmp_path / "sphere.ply"
    p = subprocess.run([sys.executable, str(example), "", str(out), "0.1"], capture_output=True,
                       text=True)
    assert p.returncode == 0, p.stderr
    m = trimesh.load(out, process=False)
    assert len(m.faces) <= 2048 and "target_reached" in p.stdout
