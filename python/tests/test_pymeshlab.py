"""`import vrsimplify.pymeshlab` loads the filter into pymeshlab 2025.7 (the wheel carries the
plugin). Skipped only where pymeshlab is absent and VRS_REQUIRE_PYMESHLAB is unset (CI sets
it)."""
import os

import pytest

from conftest import MESHES

if not os.environ.get("VRS_REQUIRE_PYMESHLAB"):
    pytest.importorskip("pymeshlab")
import pymeshlab  # noqa: E402


def test_filter_loads_and_simplifies():
    import vrsimplify.pymeshlab as vp
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(MESHES / "fandisk.off"))
    faces = ms.current_mesh().face_number()
    result = vp.apply(ms, targetfacenum=faces // 10)
    assert ms.current_mesh().face_number() <= faces // 10
    assert result["stop_reason"] == "target_reached" and result["target_reached"]
    assert result["target_faces"] == faces // 10 and result["stop_detail"] == ""
    assert result["stop_cause"] == "none"
    # Both call styles answer alike: the stop reason as text, as the numpy API's report.
    raw = ms.apply_filter(vp.FILTER, targetfacenum=100)
    assert raw["stop_reason"] == "target_reached" and raw["target_faces"] == 100


def test_meshset_method_form():
    import vrsimplify.pymeshlab  # noqa: F401
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(MESHES / "fandisk.off"))
    result = ms.meshing_decimation_vertex_removal(targetfacenum=500)
    assert ms.current_mesh().face_number() <= 500
    assert result["stop_reason"] == "target_reached"


def test_stopping_short_warns_and_says_why(tmp_path):
    """A torus cannot go below a handful of faces: asked for 2, the run stops short, warns
    with the counts, and the result says why, in both call styles."""
    import warnings

    import numpy as np
    import vrsimplify
    import vrsimplify.pymeshlab as vp
    u, w = np.meshgrid(np.linspace(0, 2 * np.pi, 24, endpoint=False),
                       np.linspace(0, 2 * np.pi, 12, endpoint=False))
    v = np.c_[((2 + np.cos(w)) * np.cos(u)).ravel(), ((2 + np.cos(w)) * np.sin(u)).ravel(),
              np.sin(w).ravel()]
    i, j = np.meshgrid(np.arange(24), np.arange(12))
    a, b = j * 24 + i, j * 24 + (i + 1) % 24
    c, d = ((j + 1) % 12) * 24 + i, ((j + 1) % 12) * 24 + (i + 1) % 24
    f = np.r_[np.c_[a.ravel(), b.ravel(), d.ravel()], np.c_[a.ravel(), d.ravel(), c.ravel()]]
    for call in (lambda ms: ms.meshing_decimation_vertex_removal(targetfacenum=2),
                 lambda ms: ms.apply_filter(vp.FILTER, targetfacenum=2)):
        ms = pymeshlab.MeshSet()
        ms.add_mesh(pymeshlab.Mesh(v, f))
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            result = call(ms)
        assert not result["target_reached"] and result["target_faces"] == 2
        assert result["stop_reason"] == "no_candidates"
        assert result["stop_detail"].startswith("remaining vertices") or \
            result["stop_detail"].startswith("stopped short"), result["stop_detail"]
        # The cause as a name, as the words say it: a price jump, or the vetoes (a torus's genus).
        jump = result["stop_detail"].startswith("stopped short")
        assert result["stop_cause"] == ("price_jump" if jump else "vetoes"), result
        short = [w for w in caught if issubclass(w.category, vrsimplify.TargetNotReachedWarning)]
        assert len(short) == 1 and "2 faces asked" in str(short[0].message)
        assert f"{ms.current_mesh().face_number()} faces kept" in str(short[0].message)
