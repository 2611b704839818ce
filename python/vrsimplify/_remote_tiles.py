"""Tile files on a file system the workers share only through fsspec (s3://, gs://, abfs://,
file://...): the driver keeps the run's own files in a local folder and mirrors each level's
tile inputs to the URL; a worker copies its tile in, runs it in a local folder and puts its
output back under a temporary name, renamed once whole (a retried task overwrites it)."""
from __future__ import annotations

import os
import shutil
import tempfile
import uuid


def open_store(url: str):
    """A fresh folder under `url` for one run: (file system, its path there)."""
    import fsspec  # with dask; needed only for URLs
    fs, root = fsspec.core.url_to_fs(url)
    path = f"{root.rstrip('/')}/vrsimplify-tiles-{uuid.uuid4().hex[:12]}"
    fs.makedirs(path, exist_ok=True)
    return fs, path


def push_level(fs, remote: str, local: str, level: int, tiles: int) -> None:
    """The state and the level's tile inputs, local -> remote."""
    fs.put_file(os.path.join(local, "state"), f"{remote}/state")
    fs.makedirs(f"{remote}/L{level}", exist_ok=True)
    for t in range(tiles):
        fs.put_file(os.path.join(local, f"L{level}", f"{t}.in"), f"{remote}/L{level}/{t}.in")


def pull_level(fs, remote: str, local: str, level: int, tiles: int) -> None:
    """The level's tile outputs, remote -> local; then the remote level goes."""
    for t in range(tiles):
        fs.get_file(f"{remote}/L{level}/{t}.out", os.path.join(local, f"L{level}", f"{t}.out"))
    fs.rm(f"{remote}/L{level}", recursive=True)


def run_tile(fs, remote: str, level: int, tile: int) -> None:
    """On a worker: the tile in, simplified in a local folder, its output out."""
    from vrsimplify import _core
    here = tempfile.mkdtemp(prefix="vrsimplify-tile-")
    try:
        os.makedirs(os.path.join(here, f"L{level}"))
        fs.get_file(f"{remote}/state", os.path.join(here, "state"))
        fs.get_file(f"{remote}/L{level}/{tile}.in", os.path.join(here, f"L{level}", f"{tile}.in"))
        _core.tiled_run_tile(here, level, tile)
        part = f"{remote}/L{level}/{tile}.out.part-{uuid.uuid4().hex[:8]}"
        fs.put_file(os.path.join(here, f"L{level}", f"{tile}.out"), part)
        fs.mv(part, f"{remote}/L{level}/{tile}.out")
    finally:
        shutil.rmtree(here, ignore_errors=True)


def remove(fs, remote: str) -> None:
    try:
        fs.rm(remote, recursive=True)
    except FileNotFoundError:
        pass
