"""The trimesh helper carries vertex colors, UVs, per-vertex attributes and face colors."""
import numpy as np
import pytest
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
    # A copy of the material, as of everything else: editing the output's leaves the input's.
    assert out.visual.material is not material
    assert np.array_equal(out.visual.material.diffuse, material.diffuse)
    out.visual.material.diffuse = [0, 0, 255, 255]
    assert np.array_equal(material.diffuse, [200, 10, 10, 255])


def test_the_trimesh_extra_brings_what_trimesh_needs(sphere):
    """`pip install vrsimplify[trimesh]`: the output's vertex normals (docs/lods.md) work."""
    import importlib.metadata
    requires = importlib.metadata.requires("vrsimplify") or []
    assert any(r.startswith("scipy") and 'extra == "trimesh"' in r for r in requires), requires
    # Where PyPI has no scipy for this Python yet (3.15), the extra cannot be installed.
    pytest.importorskip("scipy")
    out = vrsimplify.trimesh.simplify_trimesh(trimesh.Trimesh(*sphere, process=False), ratio=0.2)
    assert np.allclose(np.linalg.norm(out.vertex_normals, axis=1), 1.0)


def test_import_vrsimplify_gives_its_submodules():
    """`import vrsimplify` then `vrsimplify.trimesh....` (as the README writes it), lazily."""
    import subprocess
    import sys
    code = ("import vrsimplify, sys; assert 'vrsimplify.trimesh' not in sys.modules; "
            "print(vrsimplify.trimesh.simplify_trimesh.__name__, vrsimplify.tiled.__name__)")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert p.returncode == 0 and "simplify_trimesh vrsimplify.tiled" in p.stdout, p.stderr
    p = subprocess.run([sys.executable, "-c", "import vrsimplify; vrsimplify.nothing"],
                       capture_output=True, text=True)
    assert "has no attribute 'nothing'" in p.stderr


def test_python_m_vrsimplify_runs_the_command_line(tmp_path):
    import subprocess
    import sys
    p = subprocess.run([sys.executable, "-m", "vrsimplify", "--version"], capture_output=True,
                       text=True)
    assert p.returncode == 0 and vrsimplify.__version__ in p.stdout + p.stderr, p


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


def _two_region_sphere():
    m = trimesh.creation.icosphere(4)
    colors = np.zeros((len(m.faces), 4), np.uint8)
    colors[:, 3] = 255
    c = m.vertices[m.faces].mean(axis=1)
    inside = c[:, 0] > 0.1 * np.sin(5 * c[:, 1])  # a wavy border between two colours
    colors[inside, 0] = 255
    m.visual.face_colors = colors
    m.face_attributes["label"] = inside.astype(np.int32)
    return m


def test_face_colour_and_attribute_borders_are_seams():
    # No face takes the other region's colour (before: 20 of 556 faces on a two-colour elephant
    # at 10 %), and face attributes follow their faces.
    m = _two_region_sphere()
    out = vrsimplify.trimesh.simplify_trimesh(m, ratio=0.1)
    assert len(out.faces) <= 0.1 * len(m.faces) + 1
    c = out.vertices[out.faces].mean(axis=1)
    red = out.visual.face_colors[:, 0] == 255
    # Every output face lies in one input region: its centroid's side of the border may wobble
    # only where the border itself was straightened between kept seam vertices; its colour
    # and label agree, and both regions survive.
    assert np.array_equal(out.face_attributes["label"], red.astype(np.int32))
    inside = c[:, 0] > 0.1 * np.sin(5 * c[:, 1])
    assert (red == inside).mean() > 0.97 and red.any() and (~red).any()
    seams = out.metadata["vrsimplify"]["report"]["constrained_edges"]
    assert seams > 0


def test_a_scene_is_simplified_part_by_part():
    ball = trimesh.creation.icosphere(3)  # (trimesh's cylinder and box would need scipy)
    ball.apply_translation([3.0, 0.0, 0.0])
    scene = trimesh.Scene([_two_region_sphere(), ball])
    out = vrsimplify.trimesh.simplify_trimesh(scene, ratio=0.5)
    assert isinstance(out, trimesh.Scene) and set(out.geometry) == set(scene.geometry)
    for name, part in scene.geometry.items():
        assert len(out.geometry[name].faces) <= 0.5 * len(part.faces) + 1
        assert len(part.faces) > len(out.geometry[name].faces)  # the input scene is untouched
    with np.testing.assert_raises(TypeError):
        vrsimplify.trimesh.simplify_trimesh(np.zeros((3, 3)), ratio=0.5)
