"""Loads the MeshLab filter into pymeshlab: after ``import vrsimplify.pymeshlab``,

    ms.apply_filter("meshing_decimation_vertex_removal", targetfacenum=1000)
    ms.meshing_decimation_vertex_removal(targetfacenum=1000)  # stop reason as text

The plugin the wheel carries is built for pymeshlab 2025.7 (MeshLab 2025.07, double scalars);
pymeshlab refuses a plugin of another version, so a mismatch is an ImportError here.
"""
from __future__ import annotations

import importlib.metadata
import pathlib

import pymeshlab

PLUGIN = pathlib.Path(__file__).with_name("plugins") / "libfilter_vertex_removal.so"
PYMESHLAB_VERSION = "2025.7"  # the release the plugin was built against
FILTER = "meshing_decimation_vertex_removal"


def _load() -> None:
    if not PLUGIN.is_file():
        raise ImportError("this vrsimplify was built without the pymeshlab plugin "
                          "(scripts/build_wheel.sh builds it)")
    found = importlib.metadata.version("pymeshlab")
    if not found.startswith(PYMESHLAB_VERSION):
        raise ImportError(f"vrsimplify's plugin is built for pymeshlab {PYMESHLAB_VERSION}, "
                          f"this is pymeshlab {found}: pip install 'pymeshlab=={PYMESHLAB_VERSION}.*'")
    pymeshlab.load_plugin(str(PLUGIN))


_load()


def apply(ms: pymeshlab.MeshSet, **parameters) -> dict:
    """Runs the filter on the current mesh: pymeshlab's result dict, with the stop reason as
    text (the filter can hand pymeshlab numbers only)."""
    from . import _core

    result = dict(ms.apply_filter(FILTER, **parameters))
    result["stop_reason"] = _core.stop_reason_name(int(result["stop_reason"]))
    return result


def _method(self: pymeshlab.MeshSet, **parameters) -> dict:
    return apply(self, **parameters)


_method.__name__ = FILTER
_method.__doc__ = "Simplification: Vertex Removal Decimation (vrsimplify); parameters as apply_filter."
# pymeshlab makes a MeshSet method of each filter it ships, not of a loaded plugin's: ours too.
if not hasattr(pymeshlab.MeshSet, FILTER):
    setattr(pymeshlab.MeshSet, FILTER, _method)
