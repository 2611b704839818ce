"""The numpy API against the properties the core promises: vertices are input vertices, the
maps say where everything comes from, targets are met, topology and orientation hold, the
error bound holds, bad input raises ValueError, and the caller's arrays are never written."""
import os
import signal
import threading

import numpy as np
import pytest

import vrsimplify
from conftest import edge_face_counts, point_triangle_distances, split_sphere


def check_result(r, v, f):
    assert r.vertices.dtype == v.dtype and r.faces.dtype == f.dtype
    assert np.array_equal(r.vertices, v[r.vertex_map])  # exact input values
    assert len(np.unique(r.vertex_map)) == len(r.vertex_map)
    assert r.faces.min() >= 0 and r.faces.max() < len(r.vertices)
    kept = r.face_source >= 0
    assert np.array_equal(r.vertex_map[r.faces[kept]], f[r.face_source[kept]])
    # Each corner's source is a corner of the same input vertex.
    assert np.array_equal(f.reshape(-1)[r.corner_source], r.vertex_map[r.faces])
    before, after = edge_face_counts(f), edge_face_counts(r.vertex_map[r.faces])
    assert not [e for e, c in after.items() if c > 2 and before.get(e, 0) <= 2]
    # Orientation: on a closed, consistently oriented input every edge runs once each way.
    directed = np.concatenate([r.faces[:, [0, 1]], r.faces[:, [1, 2]], r.faces[:, [2, 0]]])
    assert len(np.unique(directed, axis=0)) == len(directed)


@pytest.mark.parametrize("ratio", [0.5, 0.1, 0.01])
def test_ratio_target_and_invariants(sphere, ratio):
    v, f = sphere
    r = vrsimplify.simplify(v, f, ratio=ratio)
    check_result(r, v, f)
    assert len(r.faces) <= round(ratio * len(f)) + 1
    assert r.report["target_reached"] and r.report["stop_reason"] == "target_reached"
    assert r.report["output_faces"] == len(r.faces)


def test_face_and_vertex_targets(fandisk):
    v, f = fandisk
    r = vrsimplify.simplify(v, f, faces=1000)
    assert len(r.faces) <= 1000 and r.report["target_reached"]
    r = vrsimplify.simplify(v, f, vertices=700)
    assert len(np.unique(r.faces)) <= 700 and r.report["target_reached"]


def test_dtypes_and_layouts_give_the_same_mesh(sphere):
    v, f = sphere
    ref = vrsimplify.simplify(v.astype(np.float32), f, ratio=0.2)
    for vv, ff in [(v.astype(np.float32), f.astype(np.int32)),
                   (np.asfortranarray(v.astype(np.float32)), f.astype(np.uint32)),
                   (np.hstack([v, v]).astype(np.float32)[:, :3], f[:, :]),
                   (v.astype(np.float32).tolist(), f.tolist())]:
        r = vrsimplify.simplify(vv, ff, ratio=0.2)
        assert np.array_equal(r.faces, ref.faces) and np.array_equal(r.vertex_map, ref.vertex_map)
    # float64 input keeps its own values (the core computes in float32).
    r = vrsimplify.simplify(v, f, ratio=0.2)
    assert r.vertices.dtype == np.float64 and np.array_equal(r.vertices, v[r.vertex_map])


def test_input_arrays_are_not_written(sphere):
    v, f = sphere[0].copy(), sphere[1].copy()
    v.flags.writeable = False
    f.flags.writeable = False
    vrsimplify.simplify(v, f, ratio=0.1)
    assert np.array_equal(v, sphere[0]) and np.array_equal(f, sphere[1])


def test_any_thread_count_gives_the_same_mesh(fandisk):
    v, f = fandisk
    one = vrsimplify.simplify(v, f, ratio=0.1, threads=1)
    two = vrsimplify.simplify(v, f, ratio=0.1, threads=2)
    assert np.array_equal(one.faces, two.faces) and np.array_equal(one.vertex_map, two.vertex_map)
    # Slid vertices included: chosen together on the workers, written in order.
    assert one.report["slid"] > 0 and one.report["slid"] == two.report["slid"]


def test_two_python_threads_at_once(sphere, fandisk):
    """The GIL is released during a run: two threads simplify side by side, each correctly."""
    results, ticks = {}, []
    def run(name, mesh):
        results[name] = vrsimplify.simplify(*mesh, ratio=0.05, threads=1,
                                            progress=lambda _: ticks.append(name))
    threads = [threading.Thread(target=run, args=(n, m))
               for n, m in (("sphere", sphere), ("fandisk", fandisk))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for name, mesh in (("sphere", sphere), ("fandisk", fandisk)):
        alone = vrsimplify.simplify(*mesh, ratio=0.05, threads=1)
        assert np.array_equal(results[name].faces, alone.faces)
    assert set(ticks) == {"sphere", "fandisk"}


def test_max_error_is_a_guarantee(sphere):
    v, f = sphere
    bound = 0.01
    r = vrsimplify.simplify(v, f, max_error=bound)
    assert 0 < r.report["error_bound"] <= bound * (1 + 1e-6)
    assert len(r.faces) < len(f) / 2
    assert r.report["slid"] == 0  # the bound is certified for the run's own faces
    # Every input vertex lies within the certified bound of the output surface.
    d = point_triangle_distances(v, r.vertices[r.faces])
    assert d.max() <= r.report["error_bound"] * (1 + 1e-4) + 1e-7
    pct = vrsimplify.simplify(v, f, max_error="0.5%")
    assert pct.report["error_bound"] <= 0.005 * vrsimplify.bounding_box_diagonal(v) * (1 + 1e-6)


def test_locked_vertices_and_seams_stay(sphere):
    v, f = sphere
    locked = v[:, 2] > 0.5
    r = vrsimplify.simplify(v, f, ratio=0.1, locked=locked)
    assert set(np.flatnonzero(locked)) <= set(r.vertex_map.tolist())
    # A seam polyline that ends: its two ends (one seam edge each) are kept.
    path = [int(np.argmax(v[:, 0]))]
    for _ in range(6):
        ring = np.unique(f[(f == path[-1]).any(axis=1)])
        ring = [x for x in ring if x not in path]
        path.append(max(ring, key=lambda x: v[x, 1]))
    seams = np.array(list(zip(path[:-1], path[1:])))
    r = vrsimplify.simplify(v, f, ratio=0.05, seams=seams)
    assert {path[0], path[-1]} <= set(r.vertex_map.tolist())


def test_progress_reports_and_cancels(fandisk):
    v, f = fandisk
    seen = []
    vrsimplify.simplify(v, f, ratio=0.1, progress=seen.append)
    assert seen and seen == sorted(seen) and seen[-1] == 1.0
    r = vrsimplify.simplify(v, f, ratio=0.01, progress=lambda x: x < 0.3)
    assert r.report["stop_reason"] == "cancelled" and not r.report["target_reached"]
    check_result(r, v, f)  # a valid mesh, partly simplified
    def boom(_):
        raise RuntimeError("from the callback")
    with pytest.raises(RuntimeError, match="from the callback"):
        vrsimplify.simplify(v, f, ratio=0.1, progress=boom)


@pytest.mark.parametrize("go_on", [np.True_, 1, "yes", np.float64(1.0), [0]])
def test_progress_takes_any_truthy_value(fandisk, go_on):
    # As Python's own `if`: numpy booleans, numbers and containers go on; false ones stop.
    v, f = fandisk
    r = vrsimplify.simplify(v, f, ratio=0.1, progress=lambda x: go_on)
    assert r.report["target_reached"]
    stop = type(go_on)() if not isinstance(go_on, np.generic) else go_on.dtype.type(0)
    r = vrsimplify.simplify(v, f, ratio=0.1, progress=lambda x: stop)
    assert r.report["stop_reason"] == "cancelled"
    r = vrsimplify.simplify(v, f, ratio=0.1, progress=lambda x: np.float64(x) < 0.5)
    assert r.report["stop_reason"] == "cancelled"


def test_error_bound_is_none_unless_tracked(sphere):
    v, f = sphere
    assert vrsimplify.simplify(v, f, ratio=0.5).report["error_bound"] is None
    r = vrsimplify.simplify(v, f, max_error="1%")
    assert r.report["error_bound"] > 0 and r.report["relaxed_removals"] == 0


def test_border_simplified_only_when_the_target_needs_it():
    # A square grid with its border: at 5 % the kept border (124 vertices) would take more
    # than a quarter of the faces asked for.
    n = 32
    x, y = np.meshgrid(np.arange(n + 1.0), np.arange(n + 1.0))
    v = np.stack([x.ravel(), y.ravel(), 0.1 * np.sin(x.ravel()) * np.cos(y.ravel())], axis=1)
    i = np.arange(n * (n + 1)).reshape(n, n + 1)[:, :n].ravel()
    f = np.concatenate([np.stack([i, i + 1, i + n + 2], 1), np.stack([i, i + n + 2, i + n + 1], 1)])
    border = np.unique(np.concatenate([np.arange(n + 1), np.arange(n * (n + 1), (n + 1) ** 2),
                                       np.arange(0, (n + 1) ** 2, n + 1), np.arange(n, (n + 1) ** 2, n + 1)]))
    r = vrsimplify.simplify(v, f, ratio=0.05)
    assert r.report["boundary_simplified"] and len(r.faces) <= round(0.05 * len(f))
    assert not set(border) <= set(r.vertex_map.tolist())
    kept = vrsimplify.simplify(v, f, ratio=0.05, keep_boundary=True)
    assert not kept.report["boundary_simplified"] and set(border) <= set(kept.vertex_map.tolist())
    assert not vrsimplify.simplify(v, f, ratio=0.5).report["boundary_simplified"]
    with pytest.raises(ValueError, match="max_jump"):
        vrsimplify.simplify(v, f, ratio=0.5, max_jump=-1)


def test_ctrl_c_raises_keyboard_interrupt_and_leaves_the_input(fandisk):
    v, f = fandisk[0].copy(), fandisk[1].copy()
    def interrupt(_):
        os.kill(os.getpid(), signal.SIGINT)  # as Ctrl-C: Python's handler marks it pending
    # Python's own handler, as in a terminal: a process started in the background by a
    # non-interactive shell inherits SIGINT ignored, and Python then installs none.
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        with pytest.raises(KeyboardInterrupt):
            vrsimplify.simplify(v, f, ratio=0.01, progress=interrupt)
    finally:
        signal.signal(signal.SIGINT, before)
    assert np.array_equal(v, fandisk[0]) and np.array_equal(f, fandisk[1])


def test_ctrl_c_is_prompt_during_the_set_up():
    """Ctrl-C half a second into a 1.3 M-face run (its set-up, where the core asks nothing
    for seconds) raises KeyboardInterrupt at once: the run goes on a thread of its own and
    the caller looks for signals every 20 ms."""
    import threading
    import time
    import trimesh
    m = trimesh.creation.icosphere(subdivisions=8)
    v, f = np.asarray(m.vertices), np.asarray(m.faces)
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    sent = []
    def ctrl_c():
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)
    timer = threading.Timer(0.3, ctrl_c)
    try:
        start = time.monotonic()
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            vrsimplify.simplify(v, f, ratio=0.01, threads=1)
        caught = time.monotonic()
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, before)
    assert sent and caught - sent[0] < 0.5, f"KeyboardInterrupt {caught - sent[0]:.3f} s after Ctrl-C"
    assert caught - start < 5.0
    # The interrupted run stops by itself; the next one is whole.
    small = trimesh.creation.icosphere(subdivisions=4)
    r = vrsimplify.simplify(np.asarray(small.vertices), np.asarray(small.faces), ratio=0.5)
    assert r.report["target_reached"]


@pytest.mark.parametrize("kwargs, message", [
    (dict(ratio=1.5), "ratio must be in"),
    (dict(ratio=0.5, faces=10), "at most one"),
    (dict(faces=-3), "count"),
    (dict(faces=2.5), "count"),
    (dict(mode="cubic"), "mode must be"),
    (dict(threads=-1), "threads must be"),
    (dict(feature_angle=400), "feature angle"),
    (dict(max_error=-1), "max_error must be > 0"),
    (dict(max_error="abc%"), "max_error must be"),
    (dict(locked=[1, 0]), "boolean"),
    (dict(locked=np.zeros(3, bool)), "one entry per vertex"),
    (dict(split_vertices="glue"), "split_vertices must be"),
])
def test_bad_parameters_raise_value_error(sphere, kwargs, message):
    with pytest.raises(ValueError, match=message):
        vrsimplify.simplify(*sphere, **kwargs)


def test_bad_input(sphere):
    v, f = sphere
    with pytest.raises(ValueError, match="out of range"):
        vrsimplify.simplify(v, np.vstack([f, [[0, 1, len(v)]]]))
    with pytest.raises(ValueError, match="out of range"):
        vrsimplify.simplify(v, np.vstack([f, [[0, 1, -1]]]))
    with pytest.raises(ValueError, match=r"mesh_vertices must be an \(n, 3\) array"):
        vrsimplify.simplify(v[:, :2], f)
    with pytest.raises(ValueError, match=r"mesh_faces must be a \(k, 3\) array.*shape \(15360,\)"):
        vrsimplify.simplify(v, f.reshape(-1))
    with pytest.raises(ValueError, match=r"mesh_faces must be .*shape \(5120, 2\)"):
        vrsimplify.simplify(v, f[:, :2])
    with pytest.raises(ValueError, match="mesh_vertices has dtype complex64, expected numbers"):
        vrsimplify.simplify(v.astype(np.complex64), f)
    with pytest.raises(ValueError, match="integers"):
        vrsimplify.simplify(v, f.astype(np.float64))
    # Integer positions are positions (as float16 ones and lists are): read as float64.
    grid = vrsimplify.simplify(np.round(v * 1000).astype(np.int32), f, ratio=0.5)
    assert grid.vertices.dtype == np.float64 and len(grid.faces) == len(f) // 2
    # NaN vertices and degenerate faces: a valid result that says what it worked around.
    bad_v = v.copy()
    bad_v[5] = np.nan
    bad_f = np.vstack([f, [[1, 1, 2]]])
    r = vrsimplify.simplify(bad_v, bad_f, ratio=0.2)
    assert r.report["input_issues"]["nonfinite_vertices"] == 1
    assert r.report["input_issues"]["degenerate_faces"] == 1
    assert 5 in r.vertex_map
    # Nothing to simplify is a mistake upstream, as in the command line (exit 3) and MeshLab.
    with pytest.raises(ValueError, match="the mesh has no faces"):
        vrsimplify.simplify(np.zeros((0, 3)), np.zeros((0, 3), np.int64))
    with pytest.raises(ValueError, match="the mesh has no faces"):
        vrsimplify.simplify(v, np.zeros((0, 3), np.int64))


def test_split_vertices_are_welded_for_the_run_and_split_again(sphere):
    v, f, copies, side = split_sphere(sphere)
    r = vrsimplify.simplify(v, f, ratio=0.1)
    assert r.report["input_issues"]["welded_vertices"] == copies
    assert r.report["target_reached"]
    assert np.array_equal(r.vertices, v[r.vertex_map])
    assert np.array_equal(f.reshape(-1)[r.corner_source], r.vertex_map[r.faces])
    # Each face on one side of the seam; by position, every edge is held by two faces.
    s = side[r.vertex_map[r.faces]]
    assert (s == s[:, :1]).all()
    at = np.unique(r.vertices, axis=0, return_inverse=True)[1].reshape(-1)  # position ids
    e = at[np.concatenate([r.faces[:, [0, 1]], r.faces[:, [1, 2]], r.faces[:, [2, 0]]])]
    _, counts = np.unique(np.sort(e, axis=1), axis=0, return_counts=True)
    assert (counts == 2).all(), "a crack along the seam"
    kept = vrsimplify.simplify(v, f, ratio=0.1, split_vertices="keep")
    assert kept.report["input_issues"]["welded_vertices"] == 0
    assert np.isin(np.arange(len(sphere[0]), len(v)), kept.vertex_map).all()


def test_pieces_written_in_other_orientations_keep_their_own(sphere):
    # As in core, tiled runs and the CLI: the lower half written turned over (a CAD export's
    # panels) is welded to the upper one and every face comes back as its input was.
    v, f, copies, side = split_sphere(sphere)
    lower = side[f].max(axis=1) == 0
    f = f.copy()
    f[lower] = f[lower][:, [0, 2, 1]]
    r = vrsimplify.simplify(v, f, ratio=0.1)
    assert r.report["input_issues"]["welded_vertices"] == copies
    assert r.report["input_issues"]["reoriented_faces"] == 0
    assert r.report["target_reached"]
    s = side[r.vertex_map[r.faces]]
    assert (s == s[:, :1]).all(), "a face spans the two orientations"
    p = r.vertices[r.faces]
    outward = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p.sum(axis=1)) > 0
    assert (outward == (s[:, 0] == 1)).all(), "a face turned against its input"


def test_a_soup_welds_freely_when_asked(sphere):
    v, f = sphere
    soup_v, soup_f = v[f.ravel()], np.arange(f.size).reshape(-1, 3)
    r = vrsimplify.simplify(soup_v, soup_f, ratio=0.1, split_vertices="weld")
    assert r.report["target_reached"]
    assert r.report["input_issues"]["welded_vertices"] == len(soup_v) - len(v)
    seam = vrsimplify.simplify(soup_v, soup_f, ratio=0.1)  # every face its own chart
    assert len(seam.faces) == len(soup_f)


def _torus(n=24, m=12):
    u, w = np.meshgrid(np.linspace(0, 2 * np.pi, n, endpoint=False),
                       np.linspace(0, 2 * np.pi, m, endpoint=False))
    v = np.c_[((2 + np.cos(w)) * np.cos(u)).ravel(), ((2 + np.cos(w)) * np.sin(u)).ravel(),
              np.sin(w).ravel()]
    i, j = np.meshgrid(np.arange(n), np.arange(m))
    a, b = j * n + i, j * n + (i + 1) % n
    c, d = ((j + 1) % m) * n + i, ((j + 1) % m) * n + (i + 1) % n
    return v, np.r_[np.c_[a.ravel(), b.ravel(), d.ravel()], np.c_[a.ravel(), d.ravel(), c.ravel()]]


def test_stopping_short_warns_with_the_counts_and_the_reason():
    """A torus cannot be 2 faces: the result is valid, and a TargetNotReachedWarning says how
    many faces were asked and kept and why (the command line's "target NOT reached")."""
    import warnings
    v, f = _torus()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = vrsimplify.simplify(v, f, faces=2)
    short = [w for w in caught if issubclass(w.category, vrsimplify.TargetNotReachedWarning)]
    assert len(short) == 1 and issubclass(vrsimplify.TargetNotReachedWarning, UserWarning)
    text = str(short[0].message)
    assert f"2 faces asked, {len(r.faces)} faces kept" in text and r.report["stop_detail"] in text
    assert r.report["target_faces"] == 2 and not r.report["target_reached"]
    jump = r.report["stop_detail"].startswith("stopped short")
    assert r.report["stop_cause"] == ("price_jump" if jump else "vetoes"), r.report
    assert short[0].filename == __file__  # points at the caller's line
    with warnings.catch_warnings():
        warnings.simplefilter("error", vrsimplify.TargetNotReachedWarning)
        with pytest.raises(vrsimplify.TargetNotReachedWarning):
            vrsimplify.simplify(v, f, faces=2)
        r = vrsimplify.simplify(v, f, ratio=0.5)  # reached: no warning
    assert r.report["target_faces"] == len(f) // 2 and r.report["target_reached"]


def test_a_mesh_of_nan_says_why_its_vertices_stay():
    """All-NaN positions: the vertices stay, and the words say NaN, not "locked"."""
    v, f = _torus()
    v = np.full_like(v, np.nan)
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vrsimplify.TargetNotReachedWarning)
        r = vrsimplify.simplify(v, f, ratio=0.1)
    assert len(r.faces) == len(f)
    assert "NaN" in r.report["stop_detail"] and "locked" not in r.report["stop_detail"]


def _grid(n=16):
    x, y = np.meshgrid(np.arange(n + 1.0), np.arange(n + 1.0))
    v = np.stack([x.ravel(), y.ravel(), 0.1 * np.sin(x.ravel()) * np.cos(y.ravel())], axis=1)
    i = np.arange(n * (n + 1)).reshape(n, n + 1)[:, :n].ravel()
    return v, np.concatenate([np.stack([i, i + 1, i + n + 2], 1), np.stack([i, i + n + 2, i + n + 1], 1)])


def test_boundary_and_target_keywords():
    """boundary="auto"|"keep"|"simplify" and target_faces / target_vertices; the old names still
    work, with a DeprecationWarning, and contradict each other loudly."""
    import warnings
    v, f = _grid()
    keep = vrsimplify.simplify(v, f, target_faces=40, boundary="keep")
    with pytest.warns(DeprecationWarning, match="boundary="):
        old = vrsimplify.simplify(v, f, target_faces=40, keep_boundary=True)
    assert np.array_equal(keep.faces, old.faces) and np.array_equal(keep.vertex_map, old.vertex_map)
    simplified = vrsimplify.simplify(v, f, target_faces=40, boundary="simplify")
    assert simplified.report["boundary_simplified"] or len(simplified.faces) <= 40
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        with pytest.raises(ValueError, match="exclude each other"):
            vrsimplify.simplify(v, f, simplify_boundary=True, keep_boundary=True)
        with pytest.raises(ValueError, match="at most one of .* got target_faces and faces"):
            vrsimplify.simplify(v, f, target_faces=40, faces=40)
        with pytest.raises(ValueError, match="boundary= alone"):
            vrsimplify.simplify(v, f, boundary="keep", keep_boundary=True)
    with pytest.raises(ValueError, match='boundary must be "auto", "keep" or "simplify"'):
        vrsimplify.simplify(v, f, boundary="glue")
    with pytest.raises(ValueError, match="target_faces must be a count"):
        vrsimplify.simplify(v, f, target_faces=10.5)
    with pytest.warns(DeprecationWarning, match="use target_faces="):
        old = vrsimplify.simplify(v, f, faces=100)
    new = vrsimplify.simplify(v, f, target_faces=100)
    assert np.array_equal(old.faces, new.faces) and new.report["target_faces"] == 100
    assert vrsimplify.simplify(v, f, target_vertices=50).report["target_vertices"] == 50
