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
    raw = ms.apply_filter(vp.FILTER, targetfacenum=100)
    assert isinstance(raw["stop_reason"], int)


def test_meshset_method_form():
    import vrsimplify.pymeshlab  # noqa: F401
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(MESHES / "fandisk.off"))
    result = ms.meshing_decimation_vertex_removal(targetfacenum=500)
    assert ms.current_mesh().face_number() <= 500
    assert result["stop_reason"] == "target_reached"
