"""Meshes bigger than memory: tiled, out-of-core runs, on local processes or a Dask cluster.

    import vrsimplify.tiled
    vrsimplify.tiled.simplify("scan.ply", "scan-1.ply", ratio=0.01, memory="2G")
    # on a cluster: every worker needs this package, and the work directory (a shared folder
    # or an fsspec URL)
    from dask.distributed import Client
    vrsimplify.tiled.simplify("scan.ply", "scan-1.ply", ratio=0.01, memory="2G",
                              client=Client("tcp://scheduler:8786"), workdir="/shared/tiles")

The input (.ply ascii or binary, .obj, ascii .off) is streamed once into the work directory
and cut into spatial tiles; each tile is a task that simplifies it with its border locked and
its seams (texture, normal, material borders) kept; further levels over shifted tiles release
the borders until the target is met; the output, in the input's own format, joins the tiles by
input vertex id — each vertex copied as the input holds it (every property, in its own
precision), each corner with its input corner's vt/vn/texcoord — and is the same whoever ran
the tiles. Command line: ``python -m vrsimplify.tiled IN OUT --ratio R [--scheduler ADDRESS]
[--memory 2G] [--work-dir DIR]`` (what ``vrsimplify --scheduler`` runs).
"""
from __future__ import annotations

import argparse
import math
import os
import sys
import time
from typing import Optional, Union

from . import _core, _remote_tiles

__all__ = ["simplify"]


def _run_tile(workdir: str, level: int, tile: int) -> int:
    """One Dask task: a tile, written atomically (a retried task rewrites it whole)."""
    from vrsimplify import _core as core  # imported in the worker process
    core.tiled_run_tile(workdir, level, tile)
    return tile


def _run_remote_tile(fs, remote: str, level: int, tile: int) -> int:
    """One Dask task when the work directory is a URL."""
    from vrsimplify import _remote_tiles
    _remote_tiles.run_tile(fs, remote, level, tile)
    return tile


def simplify(src: Union[str, os.PathLike], dst: Union[str, os.PathLike], *, ratio: float,
             memory: Union[str, int] = "2G", client=None, workdir: Optional[str] = None,
             workers: int = 0, retries: int = 2, progress: bool = False,
             keep_workdir: bool = False, split_vertices: Optional[str] = None) -> dict:
    """Simplifies the file `src` to `ratio` of its faces into `dst`, in tiles.

    ``dst`` is written in ``src``'s own format (.ply, .obj, .off; another is refused before any
    work): each vertex copied as ``src`` holds it (every property, in its own precision), each
    corner with its input corner's data (OBJ vt/vn, PLY texcoord), OBJ materials kept. A mesh
    the budget holds is one tile, whose output is the in-core run's (tested byte for byte on
    meshes of positions).

    Parameters
    ----------
    src, dst : str or os.PathLike
        The input file and the output file.
    ratio : float
        The share of the faces to keep.
    memory : str or int
        The budget a tile is cut for ("2G", "512M" or bytes); a tile takes a quarter of it. The
        tiles, and so the output, depend on it alone, not on who runs them.
    client : dask.distributed.Client, optional
        Tiles become its tasks (retried ``retries`` times if a worker dies); without one they
        run on ``workers`` local processes (0: the cores, at most 4).
    workdir : str, optional
        Where the tile files go, in a fresh folder made there and removed afterwards (unless
        ``keep_workdir``; default: ``dst``'s folder; about 70 bytes a face). With a client, a path
        every worker can reach, or an fsspec URL (s3://bucket/tmp, file:///shared/tmp...): the
        driver then keeps its files in ``dst``'s folder and the workers fetch and return tiles.
    workers, retries : int
        Local worker processes; retries of a task whose worker died.
    progress : bool
        Print each level's tiles and times to stderr.
    keep_workdir : bool
        Leave the work directory in place (to look at the tiles).
    split_vertices : {"seam", "weld", "keep"}, optional
        Vertices written twice at one position along a seam, as in ``vrsimplify.simplify``;
        None chooses as the command line does: "weld" when the vertices hold nothing but a
        position and no face holds per-corner data, else "seam".

    Returns
    -------
    dict
        Counts and times: ``input_faces``, ``output_faces``, ``target_faces``,
        ``target_reached``, ``stop_reason``, ``levels`` (each level's tiles, faces and time),
        ``seconds``.

    Raises
    ------
    ValueError
        With the reason (a malformed file, a full disk, an unwritable work directory); no
        output file is left behind.
    """
    src, dst = os.fspath(src), os.fspath(dst)
    refusal = _core.tiled_output_refusal(src, dst)  # before any work: never a PLY in a .off
    if refusal:
        raise ValueError(refusal)
    budget = memory if isinstance(memory, int) else _core.tiled_parse_memory(str(memory))
    if not budget:
        raise ValueError(f"memory must be a size such as 512M or 2G, got {memory!r}")
    parent = os.fspath(workdir) if workdir else (os.path.dirname(dst) or ".")
    url = "://" in parent
    if url and client is None:
        raise ValueError(f"a URL work directory ({parent}) is for Dask workers: give a client, "
                         "or a local folder")
    local = _core.tiled_make_work_dir((os.path.dirname(dst) or ".") if url else parent)
    store = _remote_tiles.open_store(parent) if url else None
    t0 = time.perf_counter()
    levels = []
    try:
        level = _core.tiled_begin(src, local, float(ratio), _core.tiled_faces_for_memory(budget),
                                  split_vertices or "")
        input_faces = level["faces"]
        while level["tiles"]:
            t, n, k = time.perf_counter(), level["tiles"], level["level"]
            if client is None:
                _core.tiled_run_level_locally(local, level, int(workers), bool(progress))
            else:
                if progress:
                    print(f"level {k}: {level['faces']} faces in {n} tiles on Dask, "
                          f"keeping {level['ratio']:.3g}", file=sys.stderr)
                if store:
                    _remote_tiles.push_level(*store, local, k, n)
                    run, head = _run_remote_tile, [store[0], store[1]]
                else:
                    run, head = _run_tile, [local]
                if level.get("serial"):  # tiles of the whole budget: one at a time
                    for tile in range(n):
                        client.submit(run, *head, k, tile, pure=False, retries=retries).result()
                else:
                    client.gather(client.map(run, *[[h] * n for h in head], [k] * n, range(n),
                                             pure=False, retries=retries))
                if store:
                    _remote_tiles.pull_level(*store, local, k, n)
            levels.append({**level, "seconds": time.perf_counter() - t})
            level = _core.tiled_next_level(local)
        output_faces = _core.tiled_finish(local, dst)
    finally:
        if not keep_workdir:
            _core.tiled_discard(local)
            if store:
                _remote_tiles.remove(*store)
    target = int(math.floor(ratio * input_faces + 0.5))  # as the core rounds it (llround)
    return {"input_faces": input_faces, "output_faces": output_faces, "target_faces": target,
            "target_reached": output_faces <= target,
            "stop_reason": "target_reached" if output_faces <= target else "no_candidates",
            "levels": levels,
            "faces_per_tile": _core.tiled_faces_for_memory(budget),
            "seconds": time.perf_counter() - t0, "workdir": local}


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m vrsimplify.tiled", description=__doc__.split("\n\n")[0])
    p.add_argument("input")
    p.add_argument("output")
    p.add_argument("--ratio", type=float, required=True)
    p.add_argument("--memory", default="2G")
    p.add_argument("--scheduler", help="a Dask scheduler's address (tcp://host:8786)")
    p.add_argument("--work-dir")
    p.add_argument("--workers", type=int, default=0)
    p.add_argument("--split-vertices", choices=("seam", "weld", "keep"))
    args = p.parse_args(argv)
    client = None
    if args.scheduler:
        from dask.distributed import Client
        client = Client(args.scheduler)
    try:
        r = simplify(args.input, args.output, ratio=args.ratio, memory=args.memory, client=client,
                     workdir=args.work_dir, workers=args.workers, progress=True,
                     split_vertices=args.split_vertices)
    except ValueError as e:
        print(f"vrsimplify: {e}", file=sys.stderr)
        return 1
    finally:
        if client is not None:
            client.close()
    print(f"tiled:   {r['input_faces']} -> {r['output_faces']} faces (target {r['target_faces']}) "
          f"in {len(r['levels'])} levels, {r['seconds']:.3f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
