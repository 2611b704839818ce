"""Meshes for the package's tests: generated ones, and the repository's shipped meshes (read
with trimesh, which the test extra installs). The tests run against the installed package,
never the build tree (CI installs the wheel into a fresh virtual environment)."""
import pathlib

import numpy as np
import pytest
import trimesh

MESHES = pathlib.Path(__file__).resolve().parents[2] / "meshes"


@pytest.fixture(scope="session")
def sphere():
    m = trimesh.creation.icosphere(subdivisions=4)  # 5 120 faces, closed
    return np.asarray(m.vertices, dtype=np.float64), np.asarray(m.faces, dtype=np.int64)


@pytest.fixture(scope="session")
def fandisk():
    m = trimesh.load(MESHES / "fandisk.off", process=False)
    return np.asarray(m.vertices), np.asarray(m.faces)


def edge_face_counts(faces):
    """Undirected edge -> number of faces holding it."""
    e = np.sort(np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]), axis=1)
    keys, counts = np.unique(e, axis=0, return_counts=True)
    return {tuple(k): c for k, c in zip(keys.tolist(), counts.tolist())}


def point_triangle_distances(points, tris):
    """Distance of each point to the nearest triangle (brute force; small meshes only)."""
    best = np.full(len(points), np.inf)
    for a, b, c in tris:
        best = np.minimum(best, _to_triangle(points, a, b, c))
    return best


def _to_triangle(p, a, b, c):
    # Ericson, Real-Time Collision Detection 5.1.5, vectorised over the points.
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = ap @ ab, ap @ ac
    bp = p - b
    d3, d4 = bp @ ab, bp @ ac
    cp = p - c
    d5, d6 = cp @ ab, cp @ ac
    va, vb, vc = d3 * d6 - d5 * d4, d5 * d2 - d1 * d6, d1 * d4 - d3 * d2
    denom = va + vb + vc
    with np.errstate(divide="ignore", invalid="ignore"):
        v = vb / denom
        w = vc / denom
    q = a + np.outer(v, ab) + np.outer(w, ac)  # inside the face
    with np.errstate(divide="ignore", invalid="ignore"):
        t_ab = np.clip(d1 / (d1 - d3), 0, 1)
        t_ac = np.clip(d2 / (d2 - d6), 0, 1)
        t_bc = np.clip((d4 - d3) / ((d4 - d3) + (d5 - d6)), 0, 1)
    on_ab = a + np.outer(np.nan_to_num(t_ab), ab)
    on_ac = a + np.outer(np.nan_to_num(t_ac), ac)
    on_bc = b + np.outer(np.nan_to_num(t_bc), c - b)
    inside = (va >= 0) & (vb >= 0) & (vc >= 0) & (denom > 0)
    dist = np.min([np.linalg.norm(p - on_ab, axis=1), np.linalg.norm(p - on_ac, axis=1),
                   np.linalg.norm(p - on_bc, axis=1)], axis=0)
    return np.where(inside, np.linalg.norm(p - q, axis=1), dist)


def split_sphere(sphere):
    """The sphere with its upper faces on copies of the vertices they share with the lower."""
    v, f = sphere
    upper = v[f].mean(axis=1)[:, 2] > 0
    shared = np.intersect1d(f[upper].ravel(), f[~upper].ravel())
    copy = np.full(len(v), -1)
    copy[shared] = len(v) + np.arange(len(shared))
    f2 = f.copy()
    f2[upper] = np.where(copy[f[upper]] >= 0, copy[f[upper]], f[upper])
    side = np.zeros(len(v) + len(shared), int)
    side[f2[upper].ravel()] = 1
    return np.vstack([v, v[shared]]), f2, len(shared), side
