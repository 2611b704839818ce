"""Loads the MeshLab filter into pymeshlab: after ``import vrsimplify.pymeshlab``,

    ms.meshing_decimation_vertex_removal(targetfacenum=1000)
    ms.apply_filter("meshing_decimation_vertex_removal", targetfacenum=1000)

Both give the same dict: the filter's numbers, ``stop_reason`` as text, ``stop_cause`` and
``stop_detail`` (what the command line's ``why:`` line says), as the numpy API's report. A run that stops short
of its target warns (``vrsimplify.TargetNotReachedWarning``), as ``vrsimplify.simplify`` does.

The plugin the wheel carries is built for pymeshlab 2025.7 (MeshLab 2025.07, double scalars);
pymeshlab refuses a plugin of another version, so a mismatch is an ImportError here.
"""
from __future__ import annotations

import ctypes
import functools
import importlib.metadata
import json
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


def _last_report() -> dict:
    """The plugin's last report as the core writes it (pymeshlab's result takes numbers only).
    The plugin is loaded already: dlopen of its path hands back the same library."""
    try:
        read = ctypes.CDLL(str(PLUGIN)).vrs_filter_last_report
    except (OSError, AttributeError):
        return {}
    read.restype = ctypes.c_char_p
    text = read() or b""
    return json.loads(text) if text else {}


def _finish(result) -> dict:
    """pymeshlab's numbers as the numpy API's report: the stop reason as text, its detail and
    cause."""
    from . import _core, _warn_if_short

    result = dict(result)
    if isinstance(result.get("stop_reason"), int):
        result["stop_reason"] = _core.stop_reason_name(result["stop_reason"])
    last = _last_report()
    result["stop_detail"] = last.get("stop_detail", "")
    result["stop_cause"] = last.get("stop_cause", "none")
    _warn_if_short(result, stacklevel=4)
    return result


def apply(ms: pymeshlab.MeshSet, **parameters) -> dict:
    """Runs the filter on the current mesh: the result as ``vrsimplify.simplify``'s report."""
    return ms.apply_filter(FILTER, **parameters)


def _method(self: pymeshlab.MeshSet, **parameters) -> dict:
    return apply(self, **parameters)


_method.__name__ = FILTER
_method.__doc__ = "Simplification: Vertex Removal Decimation (vrsimplify); parameters as apply_filter."
# pymeshlab makes a MeshSet method of each filter it ships, not of a loaded plugin's: ours too.
if not hasattr(pymeshlab.MeshSet, FILTER):
    setattr(pymeshlab.MeshSet, FILTER, _method)

# Both call styles give the same dict: apply_filter answers for this filter as the method does.
if not getattr(pymeshlab.MeshSet.apply_filter, "_vrsimplify", False):
    _apply_filter = pymeshlab.MeshSet.apply_filter

    @functools.wraps(_apply_filter)
    def _apply_filter_same_answer(self, filter_name, *args, **kwargs):
        result = _apply_filter(self, filter_name, *args, **kwargs)
        return _finish(result) if filter_name == FILTER else result

    _apply_filter_same_answer._vrsimplify = True
    pymeshlab.MeshSet.apply_filter = _apply_filter_same_answer
