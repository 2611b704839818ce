"""Properties of a pymeshlab mesh the tests assert (numpy only, no other geometry library)."""
import collections

import numpy as np


def snapshot(mesh):
    """Everything a failed filter must leave as it was."""
    return (mesh.vertex_matrix().copy(), mesh.face_matrix().copy())


def same(a, b):
    return all(np.array_equal(x, y) for x, y in zip(a, b))


def is_vertex_subset(out_vertices, in_vertices):
    """Every output vertex is an input vertex, bit for bit."""
    inputs = {tuple(v) for v in in_vertices.tolist()}
    return all(tuple(v) in inputs for v in out_vertices.tolist())


def edge_counts(faces):
    """Undirected edge -> number of faces, and directed edge -> count."""
    undirected, directed = collections.Counter(), collections.Counter()
    for f in faces.tolist():
        for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
            undirected[(min(a, b), max(a, b))] += 1
            directed[(a, b)] += 1
    return undirected, directed


def nonmanifold_edges(faces):
    undirected, _ = edge_counts(faces)
    return sum(1 for c in undirected.values() if c > 2)


def repeated_directed_edges(faces):
    """A directed edge used twice: a flipped face or a fold in an oriented mesh."""
    _, directed = edge_counts(faces)
    return sum(1 for c in directed.values() if c > 1)


def degenerate_faces(faces):
    return int(np.sum((faces[:, 0] == faces[:, 1]) | (faces[:, 1] == faces[:, 2]) |
                      (faces[:, 0] == faces[:, 2])))


def euler(vertices, faces):
    undirected, _ = edge_counts(faces)
    used = len(np.unique(faces))
    return used - len(undirected) + len(faces)
