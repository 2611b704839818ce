"""Fixtures for the tests that drive the real pymeshlab with our plugin.

Paths come from the environment (ctest sets them, see tests/CMakeLists.txt):
VRS_PYMESHLAB_PLUGIN   the plugin built for pymeshlab (MeshLab 2025.07, double scalars)
VRS_WRONG_PLUGINS      builds for other hosts, ':'-separated, that pymeshlab must refuse
VRS_MESHES             the repository's meshes/ folder
VRS_CGAL_DATA          CGAL's data/meshes folder
"""
import os
import pathlib

import pymeshlab
import pytest

FILTER = "meshing_decimation_vertex_removal"


def _path(name):
    value = os.environ.get(name)
    if not value:
        pytest.fail(f"{name} is not set (run the tests through ctest, see tests/CMakeLists.txt)")
    return pathlib.Path(value)


@pytest.fixture(scope="session")
def plugin():
    """Loads the plugin once into this interpreter (pymeshlab keeps plugins for the process)."""
    path = _path("VRS_PYMESHLAB_PLUGIN")
    assert path.is_file(), f"{path} not built"
    pymeshlab.load_plugin(str(path))
    return path


@pytest.fixture(scope="session")
def meshes():
    return _path("VRS_MESHES")


@pytest.fixture(scope="session")
def cgal():
    return _path("VRS_CGAL_DATA")


@pytest.fixture(scope="session")
def wrong_plugins():
    return [pathlib.Path(p) for p in os.environ.get("VRS_WRONG_PLUGINS", "").split(":") if p]
