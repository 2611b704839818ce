"""Levels of detail from Python: vrsimplify.lods() nests its levels and orders the vertices
coarsest first, write_glb() writes a binary glTF that reads back level by level with the
input's own positions, texture coordinates split at seams."""
import json
import struct

import numpy as np
import pytest

import vrsimplify

from conftest import edge_face_counts


def read_glb(path):
    data = open(path, "rb").read()
    magic, version, length = struct.unpack_from("<III", data, 0)
    assert (magic, version, length) == (0x46546C67, 2, len(data))
    json_bytes, kind = struct.unpack_from("<II", data, 12)
    assert kind == 0x4E4F534A
    doc = json.loads(data[20:20 + json_bytes])
    bin_start = 20 + json_bytes + 8
    return doc, data, bin_start


def accessor(doc, data, bin_start, index, stride=None):
    a = doc["accessors"][index]
    view = doc["bufferViews"][a["bufferView"]]
    start = bin_start + view.get("byteOffset", 0) + a.get("byteOffset", 0)
    width = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[a["type"]]
    dtype = {5126: np.float32, 5125: np.uint32, 5123: np.uint16, 5121: np.uint8}[a["componentType"]]
    step = view.get("byteStride", width * np.dtype(dtype).itemsize)
    rows = [np.frombuffer(data, dtype, width, start + i * step) for i in range(a["count"])]
    return np.array(rows)


def test_levels_nest_and_share_one_order(sphere):
    v, f = sphere
    chain = vrsimplify.lods(v, f, [0.05, 1, 0.5, 0.2])
    assert [lv.ratio for lv in chain.levels] == [1.0, 0.5, 0.2, 0.05]
    assert len(chain.levels[0].faces) == len(f)
    assert np.array_equal(chain.vertices, v[chain.order])
    finer = None
    for lv in chain.levels:
        assert lv.faces.max() < lv.vertex_count and np.array_equal(lv.vertex_map, chain.order[:lv.vertex_count])
        used = set(lv.vertex_map[np.unique(lv.faces)].tolist())
        assert len(used) == lv.vertex_count, "the prefix holds exactly the level's vertices"
        assert finer is None or used <= finer, "a coarser level's vertices are the finer one's"
        finer = used
        assert len(lv.faces) <= max(lv.ratio * len(f), 4) + 2 or not lv.report["target_reached"]
        counts = edge_face_counts(lv.faces)
        assert set(counts.values()) == {2}, "each level of a closed sphere stays closed"
        real = lv.face_source >= 0
        assert np.array_equal(np.sort(lv.vertex_map[lv.faces[real]], axis=1),
                              np.sort(f[lv.face_source[real]], axis=1))


def test_bad_levels_raise(sphere):
    v, f = sphere
    for bad in ([], [0], [1.5], ["x"], [float("nan")]):
        with pytest.raises(ValueError):
            vrsimplify.lods(v, f, bad)
    with pytest.raises(ValueError):
        vrsimplify.lods(v, f, [0.5], corner_keys=np.zeros((3, 3), np.int64))


def test_glb_reads_back_level_by_level(sphere, tmp_path):
    v, f = sphere
    v32 = v.astype(np.float32)
    chain = vrsimplify.lods(v32, f, [1, 0.25, 0.02])
    normals = v32 / np.linalg.norm(v32, axis=1, keepdims=True)
    layout = vrsimplify.write_glb(tmp_path / "s.glb", v32, chain, normals=normals,
                                  colors=np.full((len(v), 3), 200, np.uint8),
                                  level_errors=[0, 0.01, 0.1])
    doc, data, bin_start = read_glb(tmp_path / "s.glb")
    assert layout["file_bytes"] == len(data)
    assert doc["nodes"][0]["extensions"]["MSFT_lod"]["ids"] == [1, 2]
    assert layout["levels"][-1]["bytes_to_draw"] < 0.1 * len(data)
    for k, lv in enumerate(chain.levels):
        prim = doc["meshes"][k]["primitives"][0]
        assert doc["meshes"][k]["extras"]["vrsimplify"]["error"] == [0, 0.01, 0.1][k]
        pos = accessor(doc, data, bin_start, prim["attributes"]["POSITION"])
        idx = accessor(doc, data, bin_start, prim["indices"]).reshape(-1, 3)
        assert len(pos) == lv.vertex_count
        assert np.array_equal(pos, v32[lv.vertex_map]), "positions are the input's, bit for bit"
        assert np.array_equal(idx, lv.faces)
        color = accessor(doc, data, bin_start, prim["attributes"]["COLOR_0"])
        assert (color[:, :3] == 200).all() and (color[:, 3] == 255).all()


def test_compressed_glb_is_smaller_and_says_it_needs_the_extension(sphere, tmp_path):
    v, f = sphere
    v32 = v.astype(np.float32)
    chain = vrsimplify.lods(v32, f, [1, 0.25, 0.02])
    plain = vrsimplify.write_glb(tmp_path / "p.glb", v32, chain)
    packed = vrsimplify.write_glb(tmp_path / "c.glb", v32, chain, compress=True)
    assert packed["compressed"] and not plain["compressed"]
    assert packed["file_bytes"] < 0.8 * plain["file_bytes"]
    doc, data, _ = read_glb(tmp_path / "c.glb")
    assert doc["extensionsRequired"] == ["EXT_meshopt_compression"]
    assert doc["buffers"][1]["extensions"]["EXT_meshopt_compression"]["fallback"] is True
    views = [bv["extensions"]["EXT_meshopt_compression"] for bv in doc["bufferViews"]]
    assert {x["mode"] for x in views} == {"ATTRIBUTES", "TRIANGLES"}
    # Every coarser level names its bytes of the vertex stream; the viewer decodes those alone.
    assert all(doc["meshes"][k]["extras"]["vrsimplify"]["streamBytes"] > 0 for k in range(3))
    assert layout_levels_grow(packed)


def layout_levels_grow(layout):
    draws = [lv["bytes_to_draw"] for lv in layout["levels"]]
    return all(a > b for a, b in zip(draws, draws[1:]))


def test_corner_uvs_split_only_at_seams(tmp_path):
    # A strip of two texture charts: the seam's vertices are written twice, nothing else.
    n = 12
    x, y = np.meshgrid(np.arange(n + 1, dtype=np.float32), np.arange(n + 1, dtype=np.float32))
    v = np.stack([x.ravel(), y.ravel(), np.zeros(x.size, np.float32)], axis=1)
    i = (np.arange(n)[:, None] * (n + 1) + np.arange(n)[None, :]).ravel()
    f = np.concatenate([np.stack([i, i + 1, i + n + 2], 1), np.stack([i, i + n + 2, i + n + 1], 1)])
    chart = (v[f].mean(axis=1)[:, 0] >= n / 2).astype(np.int64)
    uv = v[f][:, :, :2] / n + chart[:, None, None] * [2.0, 0.0]
    keys = np.repeat(chart[:, None], 3, axis=1)
    chain = vrsimplify.lods(v, f, [1, 0.3], corner_keys=keys, simplify_boundary=True)
    layout = vrsimplify.write_glb(tmp_path / "uv.glb", v, chain, corner_uvs=uv, texture="t.png")
    assert layout["gltf_vertices"] == len(v) + n + 1
    doc, data, bin_start = read_glb(tmp_path / "uv.glb")
    assert doc["images"] == [{"uri": "t.png"}]
    prim = doc["meshes"][1]["primitives"][0]
    tex = accessor(doc, data, bin_start, prim["attributes"]["TEXCOORD_0"])
    idx = accessor(doc, data, bin_start, prim["indices"]).reshape(-1, 3)
    side = tex[idx][:, :, 0] >= 1.5
    assert (side.all(axis=1) | ~side.any(axis=1)).all(), "a face spans both charts"
    with pytest.raises(ValueError):
        vrsimplify.write_glb(tmp_path / "bad.glb", v, chain, corner_uvs=uv[:5])
    assert not (tmp_path / "bad.glb").exists()


def test_serve_streams_ranges_and_the_page(sphere, tmp_path):
    """`vrsimplify serve` (the installed console script): the page and three.js from the
    package, byte ranges of the .glb, the texture it names, nothing else."""
    import subprocess
    import urllib.error
    import urllib.request

    v, f = sphere
    chain = vrsimplify.lods(v, f, [1, 0.1])
    (tmp_path / "img").mkdir()
    (tmp_path / "img" / "t.png").write_bytes(b"\x89PNG fake")
    (tmp_path / "secret.txt").write_text("no")
    vrsimplify.write_glb(tmp_path / "m.glb", v, chain, uvs=v[:, :2], texture="img/t.png")
    server = subprocess.Popen(["vrsimplify", "serve", str(tmp_path / "m.glb"), "--port", "0"],
                              stdout=subprocess.PIPE, text=True)
    try:
        line = server.stdout.readline()
        base = line.split(" at ")[1].split()[0]
        get = lambda path, **h: urllib.request.urlopen(urllib.request.Request(base + path, headers=h))
        page = get("").read().decode()
        assert "viewer.js" in page, "/ leads to the page"
        assert b"GLTFLoader" in get("three/examples/jsm/loaders/GLTFLoader.js").read()
        assert get("three/build/three.module.js").status == 200
        whole = (tmp_path / "m.glb").read_bytes()
        r = get("m.glb", Range="bytes=100-199")
        assert r.status == 206 and r.read() == whole[100:200]
        assert r.headers["Content-Range"] == f"bytes 100-199/{len(whole)}"
        assert get("m.glb", Range="bytes=-16").read() == whole[-16:]
        assert get("img/t.png").read() == b"\x89PNG fake"
        for bad in ("secret.txt", "../secret.txt", "%2e%2e/secret.txt", "node_modules/x.js"):
            with pytest.raises(urllib.error.HTTPError) as e:
                get(bad)
            assert e.value.code == 404, bad
        with pytest.raises(urllib.error.HTTPError) as e:
            get("m.glb", Range=f"bytes={len(whole)}-")
        assert e.value.code == 416
    finally:
        server.terminate()
        server.wait(10)


def test_serve_throttles_the_model_not_the_page(sphere, tmp_path):
    """`--throttle` holds the .glb to its rate; the page and three.js, which a browser caches,
    come at full speed (a 1 MB three.js at the model's rate would cost every page load)."""
    import subprocess
    import time
    import urllib.request

    v, f = sphere
    vrsimplify.write_glb(tmp_path / "m.glb", v, vrsimplify.lods(v, f, [1, 0.1]))
    size = (tmp_path / "m.glb").stat().st_size
    rate = 4 * size  # the whole .glb in a quarter of a second
    server = subprocess.Popen(["vrsimplify", "serve", str(tmp_path / "m.glb"), "--port", "0",
                               "--throttle", str(rate)], stdout=subprocess.PIPE, text=True)
    try:
        base = server.stdout.readline().split(" at ")[1].split()[0]

        def timed(path):
            t0 = time.monotonic()
            n = len(urllib.request.urlopen(base + path).read())
            return n, time.monotonic() - t0

        n, t = timed("m.glb")
        assert n == size and t >= 0.2, f"{n} bytes of the model in {t:.3f} s at {rate} B/s"
        n, t = timed("three/build/three.module.js")
        assert n > 2 * rate and t < n / rate / 4, f"three.js: {n} bytes in {t:.3f} s"
    finally:
        server.terminate()
        server.wait(10)
