"""vrsimplify: vertex-removal mesh simplification (Pivec & Domiter, "A General Simplification
Algorithm"). Every output vertex is an input vertex, untouched: any per-vertex data follows
through ``Result.vertex_map``, per-face and per-corner data through ``face_source`` and
``corner_source``.

    import vrsimplify
    r = vrsimplify.simplify(vertices, faces, ratio=0.1)
    r.vertices, r.faces, r.report["stop_reason"]
"""
from __future__ import annotations

import atexit
import dataclasses
import importlib
import warnings
from typing import Callable, Optional, TypedDict, Union

import numpy as np

from . import _core, polygons

__version__: str = _core.__version__
# A run left to Ctrl-C stops at its next step on its own thread: wait for it before Python
# finalizes.
atexit.register(_core.wait_abandoned_runs)
__all__ = ["simplify", "Result", "Report", "TargetNotReachedWarning", "bounding_box_diagonal",
           "lods", "Lods", "LodLevel", "write_glb", "progressive", "Progressive",
           "read_progressive"]

# Imported on first use (``vrsimplify.trimesh``): each needs a package the core does not.
_SUBMODULES = ("trimesh", "pymeshlab", "tiled", "serve")


def __getattr__(name: str):
    if name in _SUBMODULES:
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


class TargetNotReachedWarning(UserWarning):
    """A run stopped short of the face or vertex count asked for: the result is valid, with
    more faces than asked. The message gives the faces asked and kept and why the run stopped
    (``report["stop_detail"]``); ``warnings.simplefilter("error", TargetNotReachedWarning)``
    makes it an exception."""


def _warn_if_short(report, stacklevel: int = 3) -> None:
    """The command line prints "target NOT reached"; Python says it as a warning."""
    if report["target_reached"] or report["stop_reason"] == "cancelled":
        return
    asked = (f"{report['target_faces']} faces" if report.get("target_faces")
             else f"{report.get('target_vertices')} vertices" if report.get("target_vertices")
             else "the target")
    detail = report.get("stop_detail") or report["stop_reason"]
    warnings.warn(f"target not reached: {asked} asked, {report['output_faces']} faces kept "
                  f"({report['stop_reason']}): {detail}", TargetNotReachedWarning,
                  stacklevel=stacklevel)


class Report(TypedDict):
    """What a run did: the same keys as the CLI's JSON and pymeshlab's dict.

    Keys
    ----
    ok : bool
        The run was made (bad input raises ValueError instead).
    input_vertices, input_faces, output_vertices, output_faces : int
        Counts before and after.
    target_faces, target_vertices : int
        The count asked for (a ratio's faces, rounded); 0 when the target is not that count.
    removed : int
        Vertices removed.
    stop_reason : str
        "target_reached", "max_factor", "last_interval", "no_candidates" (stopped short: see
        ``stop_detail``), "cancelled" (the progress callback said stop) or "error_bound".
    stop_cause : str
        When a count target was not reached, what kept the run from it, for a program to act
        on: "price_jump" (``max_jump``), "error_bound", "vetoes" (every removal left would fold
        or break the topology: the input's floor), or what keeps most of the remaining vertices
        ("boundary", "constrained", "split_seam", "locked", "nonfinite", "nonmanifold",
        "high_valence", "no_plane"); "none" when the run did not stop short.
    target_reached : bool
        False when the run stopped short (a ``TargetNotReachedWarning`` says so too).
    stop_detail : str
        When the target was not reached: what keeps the remaining vertices, in words.
    message : str
        Warnings about the input (empty if none).
    rejected : dict of str to int
        Refused removals, by the check that refused them (fold, edge_exists,
        triangle_exists, flip, degenerate, fold_over, error_bound); ``rejected_total`` sums them.
    kept : dict of str to int
        Vertices kept by a rule: boundary, nonmanifold, locked, high_valence, constrained (on
        seams or creases where they end, meet or cross).
    constrained_edges : int
        Edges kept as polylines (``seams``, ``feature_angle``, split-vertex seams).
    input_issues : dict of str to int
        degenerate_faces (dropped), nonfinite_vertices (kept with their neighbours),
        unreferenced_vertices (kept, untouched), reoriented_faces, welded_vertices (split copies
        welded for the run, see ``split_vertices``).
    relaxed_removals : int
        Removals made once the checks were eased to reach a count target.
    slid : int
        Kept vertices that gave their place, after the run, to a removed input vertex nearer
        the input (their faces kept; every vertex still an input vertex, untouched).
    boundary_simplified : bool
        The border was simplified too: kept, it alone would have taken more than a quarter of
        the faces asked for.
    max_removed_factor : float
        The highest priority (local error, mesh units) of a removal made.
    error_bound, error_bound_percent : float or None
        The certified symmetric Hausdorff bound, in mesh units and in % of the bounding-box
        diagonal; None unless ``max_error`` was given.
    seconds_simplify : float
        Wall time of the core's run.
    """

    ok: bool
    input_vertices: int
    input_faces: int
    target_faces: int
    target_vertices: int
    output_vertices: int
    output_faces: int
    removed: int
    stop_reason: str
    """"target_reached", "max_factor", "last_interval", "no_candidates", "cancelled" or
    "error_bound"."""
    stop_cause: str
    """What kept a count target from being reached ("none" when it was): see above."""
    target_reached: bool
    stop_detail: str
    """When the target was not reached: what keeps the remaining vertices, in words."""
    message: str
    """Warnings about the input (empty if none)."""
    rejected: dict[str, int]
    """Refused removals by veto (fold, edge_exists, triangle_exists, flip, degenerate,
    fold_over, error_bound)."""
    rejected_total: int
    kept: dict[str, int]
    """Vertices kept by rule (boundary, nonmanifold, locked, high_valence, constrained)."""
    constrained_edges: int
    input_issues: dict[str, int]
    """degenerate_faces (dropped), nonfinite_vertices, unreferenced_vertices (kept),
    reoriented_faces, welded_vertices (split copies welded for the run, see split_vertices)."""
    relaxed_removals: int
    slid: int
    """Kept vertices that gave their place, after the run, to a removed input vertex nearer the
    input (their faces kept; every vertex still an input vertex, untouched)."""
    boundary_simplified: bool
    max_removed_factor: float
    error_bound: Optional[float]
    """The certified symmetric Hausdorff bound in mesh units; None unless tracked."""
    error_bound_percent: Optional[float]
    seconds_simplify: float


@dataclasses.dataclass(frozen=True)
class Result:
    """A simplified mesh and where each of its parts comes from in the input.

    Attributes
    ----------
    vertices : numpy.ndarray
        (m, 3): the input's rows ``vertex_map`` names, same dtype, same values, bit for bit.
    faces : numpy.ndarray
        (k, 3): triangles, indices into ``vertices``, in the input faces' dtype.
    vertex_map : numpy.ndarray
        (m,) int64: output vertex -> input vertex; ``colors[r.vertex_map]`` carries any
        per-vertex data.
    face_source : numpy.ndarray
        (k,) int64: the input face an output face is, or -1 for a face the re-triangulation
        made.
    corner_source : numpy.ndarray
        (k, 3) int64: for each output corner, the input corner whose per-corner data (UVs,
        normals) it takes, as a flat index ``3 * face + corner`` into the input's corners
        (``uv_per_corner.reshape(-1, 2)[r.corner_source]``): the same vertex, on the same side
        of every seam. With polygon faces, ``m * face + corner`` for a (p, m) array, or the
        running count of corners for a list of faces.
    report : Report
        What the run did: counts, the target asked, ``stop_reason``, ``target_reached``,
        ``stop_detail`` and the rest (see ``vrsimplify.Report``).
    polygons : list of numpy.ndarray or None
        With polygon faces given: every input polygon the run left untouched whole, every other
        face a triangle; None for triangles.
    polygon_source : numpy.ndarray or None
        With polygon faces: for each of ``polygons`` the input face it is, or -1.
    """

    vertices: np.ndarray
    """(m, 3): the input's rows `vertex_map` names, same dtype, same values, bit for bit."""
    faces: np.ndarray
    """(k, 3): indices into `vertices`, in the input faces' dtype."""
    vertex_map: np.ndarray
    """(m,) int64: output vertex -> input vertex (`colors[vertex_map]` carries any per-vertex
    data)."""
    face_source: np.ndarray
    """(k,) int64: the input face an output face is, or -1 for a face the re-triangulation made."""
    corner_source: np.ndarray
    """(k, 3) int64: for each output corner the input corner (3 * face + corner) whose
    per-corner data (UVs, normals) it takes: the same vertex, on the same side of every seam.
    With polygon faces: the input face's and corner's indices (a face's corners counted one
    after the other: m * face + corner for a (p, m) array)."""
    report: Report
    """What the run did: counts, `stop_reason` as text, `target_reached`, `error_bound` (mesh
    units; None unless a bound was tracked), `boundary_simplified`, `relaxed_removals`, `slid`,
    `stop_detail`, warnings in `message` (see the report table in the documentation)."""
    polygons: Optional[list] = None
    """With polygon faces given: the output as polygons, each an array of indices into
    `vertices`: every input polygon the run left untouched whole, every other face a triangle
    (`faces` holds the same surface as triangles). None for triangles."""
    polygon_source: Optional[np.ndarray] = None
    """With polygon faces: for each of `polygons` the input face it is, or -1."""


def _array(a, what: str, kinds: str) -> np.ndarray:
    a = np.asarray(a)  # no copy for an ndarray of any layout: the core reads strides
    if a.dtype.kind not in kinds:
        raise ValueError(f"{what} has dtype {a.dtype}, expected "
                         + ("numbers" if "f" in kinds else "integers"))
    return a


def _vertex_array(mesh_vertices, what: str = "mesh_vertices") -> np.ndarray:
    """Vertices as float32/64, copied only when another dtype (float16, integers, lists)."""
    v = _array(mesh_vertices, what, "fiu")
    if v.ndim != 2 or v.shape[1] != 3:
        raise ValueError(f"{what} must be an (n, 3) array of positions, got shape {v.shape}")
    return v if v.dtype in (np.float32, np.float64) else v.astype(np.float64)


def _mesh_arrays(mesh_vertices, mesh_faces) -> tuple[np.ndarray, np.ndarray]:
    """Vertices as float32/64 and faces as 32/64-bit integers, copied only when another dtype."""
    v = _vertex_array(mesh_vertices)
    f = _array(mesh_faces, "mesh_faces", "iu")
    if f.ndim != 2 or f.shape[1] != 3:
        raise ValueError("mesh_faces must be a (k, 3) array of triangles, a (k, m) array of "
                         f"polygons or a list of faces, got shape {f.shape}")
    if f.dtype not in (np.int32, np.int64, np.uint32, np.uint64):
        f = f.astype(np.int64)
    return v, f


def _target(targets: dict, max_error) -> tuple[str, float]:
    """(kind, value) from the targets the caller gave, {keyword as written: value}."""
    given = [(name, v) for name, v in targets.items() if v is not None]
    if len(given) > 1:
        raise ValueError("give at most one of ratio, target_faces and target_vertices, got "
                         + " and ".join(name for name, _ in given))
    if given:
        name, value = given[0]
        kind = "ratio" if name == "ratio" else "faces" if name.endswith("faces") else "vertices"
        try:
            number = float(value)
        except (TypeError, ValueError):
            raise ValueError(f"{name} must be a number, got {value!r}") from None
        if kind != "ratio" and not (number >= 0 and number == int(number)):
            raise ValueError(f"{name} must be a count (a whole number >= 0), got {value!r}")
        return kind, number
    # The bound alone simplifies as far as it allows; with nothing at all, half the faces.
    return ("bound", 0.0) if max_error is not None else ("ratio", 0.5)


def _max_error(max_error, vertices: np.ndarray) -> float:
    if max_error is None:
        return 0.0
    if isinstance(max_error, str):  # "0.5%": percent of the bounding-box diagonal
        text = max_error.strip()
        try:
            value = float(text[:-1]) if text.endswith("%") else float(text)
        except ValueError:
            raise ValueError(f"max_error must be a distance or a percentage, got {max_error!r}") from None
        if text.endswith("%"):
            value = value / 100.0 * bounding_box_diagonal(vertices)
    else:
        value = float(max_error)
    if not value > 0:
        raise ValueError(f"max_error must be > 0 (math.inf tracks the bound without limit), got {max_error!r}")
    return value


def _deprecated(old: str, new: str) -> None:
    warnings.warn(f"{old} is deprecated: use {new}", DeprecationWarning, stacklevel=3)


def _boundary(boundary: str, simplify_boundary, keep_boundary) -> str:
    """The boundary rule from ``boundary`` and the deprecated pair of flags."""
    if simplify_boundary is not None or keep_boundary is not None:
        _deprecated("simplify_boundary= / keep_boundary=", 'boundary="simplify" / "keep"')
        if simplify_boundary and keep_boundary:
            raise ValueError("simplify_boundary and keep_boundary exclude each other: give "
                             'boundary="simplify" or boundary="keep"')
        if boundary != "auto":
            raise ValueError("give boundary= alone, not with simplify_boundary or keep_boundary")
        boundary = "simplify" if simplify_boundary else "keep" if keep_boundary else "auto"
    if boundary not in ("auto", "keep", "simplify"):
        raise ValueError(f'boundary must be "auto", "keep" or "simplify", got {boundary!r}')
    return boundary


def simplify(mesh_vertices, mesh_faces, /, *, ratio: Optional[float] = None,
             target_faces: Optional[int] = None, target_vertices: Optional[int] = None,
             max_error: Union[float, str, None] = None, mode: str = "surface", threads: int = 0,
             boundary: str = "auto", max_jump: float = 10.0,
             feature_angle: float = 0.0, seams=None, locked=None,
             progress: Optional[Callable[[float], Optional[bool]]] = None,
             split_vertices: str = "seam", faces: Optional[int] = None,
             vertices: Optional[int] = None, simplify_boundary: Optional[bool] = None,
             keep_boundary: Optional[bool] = None) -> Result:
    """Simplifies a triangle or polygon mesh by removing vertices; the input arrays are left
    untouched.

    Parameters
    ----------
    mesh_vertices : array_like, (n, 3)
        Positions, float32 or float64 (other numbers are read as float64).
    mesh_faces : array_like
        (k, 3) triangles of any integer dtype, or polygons: a (k, m) array (quads: m = 4) or a
        sequence of faces of any lengths, each fanned from its first corner; the polygons the
        run leaves untouched come back whole in ``Result.polygons``, and ``face_source`` /
        ``corner_source`` then name input polygons and their corners.
    ratio : float, optional
        The share of the faces to keep, in [0, 1] (the default target: 0.5).
    target_faces, target_vertices : int, optional
        A count to reach instead (at most one of ratio, target_faces and target_vertices).
    faces, vertices : int, optional
        Deprecated names of target_faces and target_vertices (``Result.faces`` is the output's
        array, not a count).
    max_error : float or str, optional
        A guaranteed symmetric Hausdorff bound, in mesh units or as a string "E%" of the
        bounding-box diagonal; alone it simplifies as far as the bound allows, with a count
        target whichever comes first; ``math.inf`` reports the certified bound without limiting
        (``report["error_bound"]``).
    mode : {"surface", "terrain", "planar"}
        3D, 2.5D (the XY plane) or 2D.
    threads : int
        0 = every core this process may use (its CPU affinity, its container's CPU quota); the
        output is the same for any number.
    boundary : {"auto", "keep", "simplify"}
        Border vertices: "auto" keeps them unless the kept border alone would take more than
        a quarter of the faces asked for (``report["boundary_simplified"]``); "keep" keeps
        every one whatever the target (the paper's rule); "simplify" removes them as any other.
    simplify_boundary, keep_boundary : bool, optional
        Deprecated: ``boundary="simplify"`` and ``boundary="keep"`` (together, a ValueError).
    max_jump : float
        Stop short of a count target rather than take a removal costing this many times the
        dearest one so far (a part dropped, a tunnel pressed flat), half as many once the
        vetoes are eased; 0: the target at any cost.
    feature_angle : float
        Keep edges whose faces turn more than this many degrees apart (0: off).
    seams : array_like, (s, 2), optional
        Vertex pairs kept as polylines (texture seams, material borders).
    locked : array_like of bool, (n,), optional
        Those vertices stay.
    progress : callable, optional
        Called with the fraction done; returning False (or any false value but None) stops
        with a valid, partial result (``stop_reason`` "cancelled"); None goes on, so a
        callback that only prints needs no return.
    split_vertices : {"seam", "weld", "keep"}
        Vertices written twice at one position along a seam (two border edges at the same two
        positions): "seam" welds them for the run and keeps each side's copies (their own data
        stays exact), "weld" welds them freely (copies that hold nothing but a position),
        "keep" leaves them apart as borders. ``report["input_issues"]["welded_vertices"]``
        counts them.

    Returns
    -------
    Result
        The output and where each of its vertices, faces and corners comes from.

    Raises
    ------
    ValueError
        Bad input or parameters, naming the parameter; a mesh without faces.
    KeyboardInterrupt
        Ctrl-C, at any point of the run (the run goes on a thread of its own).

    Warns
    -----
    TargetNotReachedWarning
        A count target the run cannot reach: the result is valid, with more faces, and the
        warning gives the faces asked and kept and why.
    """
    poly = polygons.polygon_faces(mesh_faces)
    fanned = None
    if poly is not None:
        v = _vertex_array(mesh_vertices)
        fanned = polygons.fan(*poly, len(v))
        f = fanned.triangles
    else:
        v, f = _mesh_arrays(mesh_vertices, mesh_faces)
    if faces is not None:
        _deprecated("faces=", "target_faces=")
    if vertices is not None:
        _deprecated("vertices=", "target_vertices=")
    kind, value = _target({"ratio": ratio, "target_faces": target_faces,
                           "target_vertices": target_vertices, "faces": faces,
                           "vertices": vertices}, max_error)
    boundary = _boundary(boundary, simplify_boundary, keep_boundary)
    if seams is not None:
        seams = _array(seams, "seams", "iu").astype(np.int64, copy=False)
    if locked is not None:
        locked = np.asarray(locked)
        if locked.dtype != np.bool_:
            raise ValueError(f"locked must be a boolean mask, got dtype {locked.dtype}")
    out_faces, vertex_map, face_source, corner_source, report = _core.simplify(
        v, f, kind, value, _max_error(max_error, v), str(mode), int(threads),
        boundary == "simplify", boundary == "keep", float(max_jump), float(feature_angle), seams,
        locked, progress, str(split_vertices),
        None if fanned is None else fanned.whole_flags)
    out_faces = out_faces.astype(f.dtype, copy=False)
    _warn_if_short(report)
    if fanned is None:
        return Result(vertices=v[vertex_map], faces=out_faces, vertex_map=vertex_map,
                      face_source=face_source, corner_source=corner_source, report=report)
    out_polygons, polygon_source = polygons.regroup(fanned, out_faces, face_source, vertex_map,
                                                    len(v))
    face_source, corner_source = polygons.input_sources(fanned, face_source, corner_source)
    return Result(vertices=v[vertex_map], faces=out_faces, vertex_map=vertex_map,
                  face_source=face_source, corner_source=corner_source, report=report,
                  polygons=out_polygons, polygon_source=polygon_source)


def bounding_box_diagonal(vertices) -> float:
    """Length of the bounding box's diagonal of the finite vertices (the unit of "E%")."""
    return float(_core.bounding_box_diagonal(_vertex_array(vertices, "vertices")))


from .lods import LodLevel, Lods, lods, write_glb  # noqa: E402  (needs _array above)
from .progressive import Progressive, progressive, read_progressive  # noqa: E402
