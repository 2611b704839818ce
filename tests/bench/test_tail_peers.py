#!/usr/bin/env python3
"""bench/tail_peers.py's topology reading (parts, borders, genus, edges of > 2 faces) on meshes
whose answer is known, its PLY reader on a file written as vrs_bench writes one, and what it says
a peer gave up."""
import os
import struct
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "bench"))
import tail_peers as t  # noqa: E402


def torus(n, m):
    """An n x m grid wrapped both ways: genus 1, no border."""
    at = lambda i, j: (i % n) * m + (j % m)  # noqa: E731
    faces = []
    for i in range(n):
        for j in range(m):
            faces += [(at(i, j), at(i + 1, j), at(i + 1, j + 1)), (at(i, j), at(i + 1, j + 1), at(i, j + 1))]
    return faces


def check(name, got, want):
    if got != want:
        sys.exit(f"{name}: {got}, expected {want}")


def main():
    tetra = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]
    check("tetrahedron", t.topology(tetra), (1, 0, 0, 0))
    check("torus", t.topology(torus(4, 5)), (1, 0, 1, 0))
    check("two tori", t.topology(torus(4, 5) + [tuple(v + 20 for v in f) for f in torus(3, 4)]), (2, 0, 2, 0))
    check("triangle", t.topology([(0, 1, 2)]), (1, 1, 0, 0))
    check("two triangles apart", t.topology([(0, 1, 2), (3, 4, 5)]), (2, 2, 0, 0))
    check("tetrahedron less a face", t.topology(tetra[:3]), (1, 1, 0, 0))
    check("three faces on an edge", t.topology([(0, 1, 2), (1, 0, 3), (0, 1, 4)])[3], 1)

    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "m.ply")
        with open(path, "wb") as f:
            f.write(b"ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
                    b"property float y\nproperty float z\nelement face 4\n"
                    b"property list uchar int vertex_indices\nend_header\n")
            f.write(struct.pack("<12f", 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1))
            for face in tetra:
                f.write(struct.pack("<B3i", 3, *face))
        check("ply faces", t.read_ply(path), tetra)

    base = (1, 0, 2, 0)
    check("kept", t.gave_up(base, base, 0.005, 0.0), [])
    check("folded under QECD's", t.gave_up(base, base, 0.03, 0.04), [])
    check("folded", len(t.gave_up(base, base, 0.03, 0.001)), 1)
    check("hole closed", len(t.gave_up(base, (1, 0, 1, 0), 0.0, 0.0)), 1)
    check("edge of three faces made", len(t.gave_up(base, (1, 0, 2, 1), 0.0, 0.0)), 1)
    print("tail_peers: topology, reader and verdicts as expected")


if __name__ == "__main__":
    main()
