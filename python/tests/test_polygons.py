"""Polygon faces through the numpy API: quads and mixed polygons are simplified as their fans,
every polygon the run left untouched comes back whole in Result.polygons, the maps name the
input's polygons and corners, and bad polygons raise ValueError naming the face."""
import numpy as np
import pytest

import vrsimplify


def quad_grid(n=40):
    """An n x n grid of quads over a bumpy height field: (n + 1)^2 vertices, n^2 quads."""
    x, y = np.meshgrid(np.arange(n + 1.0), np.arange(n + 1.0))
    z = 2 * np.sin(x / 5) * np.cos(y / 7)
    v = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)
    i = np.arange(n)[None, :] + (n + 1) * np.arange(n)[:, None]
    q = np.stack([i, i + 1, i + n + 2, i + n + 1], axis=-1).reshape(-1, 4)
    return v, q


def fanned(polys):
    """Each polygon as its fan from the first corner, as sorted rows (a set of triangles)."""
    tris = [(p[0], p[j], p[j + 1]) for p in polys for j in range(1, len(p) - 1)]
    return sorted(tuple(int(c) for c in t) for t in tris)


def check_polygons(r, v, polys):
    """Result.polygons against the input polygons and Result.faces."""
    assert r.polygons is not None and len(r.polygons) == len(r.polygon_source)
    # The same surface: the polygons, fanned, are the triangles of `faces`.
    assert fanned(r.polygons) == fanned(r.faces)
    whole = 0
    for p, s in zip(r.polygons, r.polygon_source):
        assert len(p) >= 3 and p.min() >= 0 and p.max() < len(r.vertices)
        if len(p) > 3:  # an untouched input polygon, corner for corner
            assert s >= 0 and np.array_equal(r.vertex_map[p], np.asarray(polys[s]))
            whole += 1
        elif s >= 0:  # a triangle of an input face: its corners are that face's
            assert set(r.vertex_map[p].tolist()) <= set(np.asarray(polys[s]).tolist())
    # face_source and corner_source name input polygons and their corners.
    corners = np.concatenate([np.asarray(p) for p in polys])
    kept = r.face_source >= 0
    for t, s in zip(r.faces[kept], r.face_source[kept]):
        assert set(r.vertex_map[t].tolist()) <= set(np.asarray(polys[s]).tolist())
    assert np.array_equal(corners[r.corner_source], r.vertex_map[r.faces])
    return whole


@pytest.mark.parametrize("ratio", [0.5, 0.1])
def test_quads_untouched_come_back_whole(ratio):
    v, q = quad_grid()
    r = vrsimplify.simplify(v, q, ratio=ratio)
    assert r.report["input_faces"] == 2 * len(q)  # the fans' triangles
    assert r.report["target_reached"] and len(r.faces) <= round(ratio * 2 * len(q)) + 1
    assert np.array_equal(r.vertices, v[r.vertex_map])
    whole = check_polygons(r, v, q)
    if ratio == 0.5:  # at 10 % every quad has lost a corner
        assert whole > 0, "some quads were left untouched and come back as quads"
    assert any(len(p) == 3 for p in r.polygons), "the rebuilt faces are triangles"


def test_mixed_polygons_as_a_list():
    v, q = quad_grid(12)
    # Pairs of neighbouring quads as hexagons, some quads split into triangles, the rest kept.
    polys = []
    for k, f in enumerate(q.tolist()):
        if k % 12 < 6 and k % 2 == 0:
            g = q[k + 1].tolist()
            polys.append([f[0], g[0], g[1], g[2], f[2], f[3]])  # f and g share f[1], f[2]
        elif k % 12 < 6:
            continue
        elif k % 3 == 0:
            polys += [[f[0], f[1], f[2]], [f[0], f[2], f[3]]]
        else:
            polys.append(f)
    r = vrsimplify.simplify(v, polys, ratio=0.8)
    assert check_polygons(r, v, polys) > 0
    assert {len(p) for p in r.polygons} >= {3, 4, 6}
    # The same polygons as arrays of any integer type give the same mesh.
    r2 = vrsimplify.simplify(v, [np.asarray(p, dtype=np.uint32) for p in polys], ratio=0.8)
    assert np.array_equal(r.faces, r2.faces) and np.array_equal(r.vertex_map, r2.vertex_map)


def test_triangles_give_no_polygons():
    v, q = quad_grid(8)
    t = np.concatenate([q[:, [0, 1, 2]], q[:, [0, 2, 3]]])
    r = vrsimplify.simplify(v, t, ratio=0.5)
    assert r.polygons is None and r.polygon_source is None


def test_quads_reach_what_their_fans_reach():
    """A quad array runs as its fans (with the polygon flag, which only keeps the slide off
    untouched quads): as many faces come out as from the fans given as triangles."""
    v, q = quad_grid(20)
    r = vrsimplify.simplify(v, q, ratio=0.3)
    t = np.stack([q[:, [0, 1, 2]], q[:, [0, 2, 3]]], axis=1).reshape(-1, 3)
    rt = vrsimplify.simplify(v, t, ratio=0.3)
    assert len(r.faces) == len(rt.faces)
    assert r.report["input_faces"] == rt.report["input_faces"]


@pytest.mark.parametrize("polys, message", [
    ([[0, 1, 2, 3], [1, 2]], "face 1 has 2 corners"),
    ([[0, 1, 2, 3], [0, 1, 2], [0, 1, 99, 2]], "face 2 has vertex index 99"),
    ([[0, 1, 2, 3], [0, -1, 2]], "face 1 has vertex index -1"),
    ([[0, 1, 2, 3], [0.5, 1, 2]], "face 1 has dtype float64"),
    (np.array([[0, 1, 2, 3]], dtype=np.float32), "faces has dtype float32"),
])
def test_bad_polygons_raise_naming_the_face(polys, message):
    v, _ = quad_grid(2)
    with pytest.raises(ValueError, match=message):
        vrsimplify.simplify(v, polys, ratio=0.5)


def test_command_line_keeps_the_polygons_the_numpy_api_keeps(tmp_path):
    """One behaviour: the console script on an OFF of quads, pentagons and hexagons writes back
    whole exactly the polygons Result.polygons keeps for the same run, in the same order of
    corners (the OFF is written with round-trip coordinates: vertices compare by position)."""
    import shutil
    import subprocess
    v, q = quad_grid(24)
    v = v.astype(np.float32).astype(np.float64)  # what 9 digits of text hold exactly
    # Quads; two of them merged into a hexagon, one split into two triangles.
    polys = [[q[5][0], q[5][1], q[6][1], q[6][2], q[5][2], q[5][3]],
             [q[7][0], q[7][1], q[7][2]], [q[7][0], q[7][2], q[7][3]]]
    polys += [list(p) for i, p in enumerate(q) if i not in (5, 6, 7)]
    src = tmp_path / "polys.off"
    src.write_text(f"OFF\n{len(v)} {len(polys)} 0\n" + "".join("%.9g %.9g %.9g\n" % tuple(x) for x in v)
                   + "".join("%d %s\n" % (len(p), " ".join(map(str, p))) for p in polys))
    r = vrsimplify.simplify(v, polys, ratio=0.5, threads=1)
    out = tmp_path / "out.off"
    subprocess.run([shutil.which("vrsimplify"), str(src), str(out), "--ratio", "0.5", "--threads", "1",
                    "--quiet"], check=True)
    lines = [line.split() for line in out.read_text().splitlines() if line.strip()]
    nv, nf = int(lines[1][0]), int(lines[1][1])
    pos = [tuple(np.float32(x) for x in w[:3]) for w in lines[2:2 + nv]]
    cli = sorted(tuple(pos[int(i)] for i in w[1:]) for w in lines[2 + nv:2 + nv + nf] if int(w[0]) > 3)
    api = sorted(tuple(tuple(np.float32(x) for x in r.vertices[i]) for i in p) for p in r.polygons if len(p) > 3)
    assert len(api) > 20 and cli == api
