"""Textured meshes, side by side in pymeshlab: our filter against MeshLab's own texture-aware
quadric decimation (meshing_decimation_quadric_edge_collapse_with_texture), same targets.

    python bench/textured_compare.py PLUGIN OUT_DIR INPUT...   (PLY texcoord lists or OBJ vt)

Per input and ratio (50 %, 10 %): faces reached, time, symmetric Hausdorff distance (MeshLab's
filter, % of the bounding-box diagonal), the texture-space error, and the share of faces whose
corners check out (tests/textured/textured_mesh.py: values of their vertex, one chart).
Texture-space error: points sampled uniformly on the original surface carry the original's
texture coordinate; the closest point of the simplified surface carries the one interpolated
from its face's corners; the error is their distance in texture units (mean and 95th
percentile; a sample whose closest point falls in another chart counts its full jump).
Writes OUT_DIR/textured.csv and the simplified meshes.
"""
import csv
import pathlib
import subprocess
import sys
import time

import numpy as np
import pymeshlab

HERE = pathlib.Path(__file__).resolve().parent
CHECK = HERE.parent / "tests" / "textured" / "textured_mesh.py"
METHODS = {
    "ours": ("meshing_decimation_vertex_removal", {}),
    "qecd_texture": ("meshing_decimation_quadric_edge_collapse_with_texture", {}),
}
SAMPLES = 4000
FAILED = []  # MeshSets in which a filter raised (pymeshlab issues #384, #399)


def closest_points(p, a, b, c):
    """Closest points of triangles (a, b, c) (F x 3) to points p (S x 3): per sample the face
    index and barycentric coordinates of the nearest point (Ericson's region tests, chunked)."""
    best_d = np.full(len(p), np.inf)
    best_f = np.zeros(len(p), dtype=np.int64)
    best_bc = np.zeros((len(p), 3))
    ab, ac = b - a, c - a
    for start in range(0, len(p), 64):
        q = p[start:start + 64, None, :]  # S x 1 x 3
        ap = q - a
        d1, d2 = (ab * ap).sum(-1), (ac * ap).sum(-1)
        bp = q - b
        d3, d4 = (ab * bp).sum(-1), (ac * bp).sum(-1)
        cp = q - c
        d5, d6 = (ab * cp).sum(-1), (ac * cp).sum(-1)
        va, vb, vc = d3 * d6 - d5 * d4, d5 * d2 - d1 * d6, d1 * d4 - d3 * d2
        with np.errstate(divide="ignore", invalid="ignore"):
            denom = va + vb + vc
            v = np.where(denom != 0, vb / denom, 0)
            w = np.where(denom != 0, vc / denom, 0)
            # Edge and vertex regions override the face region, as in Ericson's routine.
            t_ab = np.clip(d1 / (d1 - d3), 0, 1)
            t_ac = np.clip(d2 / (d2 - d6), 0, 1)
            t_bc = np.clip((d4 - d3) / ((d4 - d3) + (d5 - d6)), 0, 1)
        u_ = 1 - v - w
        bc = np.stack([u_, v, w], -1)
        region = [
            ((d1 <= 0) & (d2 <= 0), [1, 0, 0]),
            ((d3 >= 0) & (d4 <= d3), [0, 1, 0]),
            ((d6 >= 0) & (d5 <= d6), [0, 0, 1]),
        ]
        edge = [
            ((vc <= 0) & (d1 >= 0) & (d3 <= 0), lambda: np.stack([1 - t_ab, t_ab, 0 * t_ab], -1)),
            ((vb <= 0) & (d2 >= 0) & (d6 <= 0), lambda: np.stack([1 - t_ac, 0 * t_ac, t_ac], -1)),
            ((va <= 0) & ((d4 - d3) >= 0) & ((d5 - d6) >= 0),
             lambda: np.stack([0 * t_bc, 1 - t_bc, t_bc], -1)),
        ]
        for mask, value in reversed(edge):
            bc = np.where(mask[..., None], np.nan_to_num(value()), bc)
        for mask, value in reversed(region):
            bc = np.where(mask[..., None], np.array(value, dtype=float), bc)
        x = bc[..., :1] * a + bc[..., 1:2] * b + bc[..., 2:] * c
        d = ((x - q) ** 2).sum(-1)
        f = d.argmin(1)
        rows = np.arange(len(f))
        best_d[start:start + 64] = d[rows, f]
        best_f[start:start + 64] = f
        best_bc[start:start + 64] = bc[rows, f]
    return best_f, best_bc


def texture_error(original, simplified, rng):
    vo, fo, wo = original
    vs, fs, ws = simplified
    a, b, c = vo[fo[:, 0]], vo[fo[:, 1]], vo[fo[:, 2]]
    area = np.linalg.norm(np.cross(b - a, c - a), axis=1)
    faces = rng.choice(len(fo), SAMPLES, p=area / area.sum())
    r1, r2 = rng.random(SAMPLES), rng.random(SAMPLES)
    s = np.sqrt(r1)
    bc = np.stack([1 - s, s * (1 - r2), s * r2], -1)
    points = (bc[:, :, None] * vo[fo[faces]]).sum(1)
    uv_true = (bc[:, :, None] * wo[faces]).sum(1)
    f, bcs = closest_points(points, vs[fs[:, 0]], vs[fs[:, 1]], vs[fs[:, 2]])
    uv_got = (bcs[:, :, None] * ws[f]).sum(1)
    err = np.linalg.norm(uv_got - uv_true, axis=1)
    return float(err.mean()), float(np.percentile(err, 95))


def arrays(m):
    return (m.vertex_matrix().astype(np.float64), m.face_matrix(),
            m.wedge_tex_coord_matrix().reshape(-1, 3, 2).astype(np.float64))


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    plugin, out = sys.argv[1], pathlib.Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    pymeshlab.load_plugin(str(pathlib.Path(plugin).resolve()))
    rows = []
    for source in map(pathlib.Path, sys.argv[3:]):
        for ratio in (0.5, 0.1):
            for method, (name, extra) in METHODS.items():
                ms = pymeshlab.MeshSet()
                ms.load_new_mesh(str(source))
                original = arrays(ms.current_mesh())
                diagonal = ms.current_mesh().bounding_box().diagonal()
                faces = ms.current_mesh().face_number()
                target = round(faces * ratio)
                ms.apply_filter("generate_copy_of_current_mesh")
                start = time.perf_counter()
                try:
                    ms.apply_filter(name, targetfacenum=target, **extra)
                except pymeshlab.PyMeshLabException as e:  # a peer may refuse an input
                    reason = str(e).split("Details: ")[-1].strip()
                    rows.append(dict(mesh=source.name, ratio=ratio, method=method,
                                     input_faces=faces, target=target,
                                     faces=f"refused: {reason}", seconds="-",
                                     hausdorff_max="-", hausdorff_mean="-", texture_mean="-",
                                     texture_p95="-", corners_ok="-"))
                    print(rows[-1], flush=True)
                    FAILED.append(ms)  # pymeshlab crashes later if it is destroyed
                    continue
                seconds = time.perf_counter() - start
                result = ms.current_mesh()
                path = out / f"{source.stem}-{int(ratio * 100)}-{method}{source.suffix}"
                ms.save_current_mesh(str(path))
                there = ms.get_hausdorff_distance(sampledmesh=1, targetmesh=0, samplenum=50000)
                back = ms.get_hausdorff_distance(sampledmesh=0, targetmesh=1, samplenum=50000)
                tex_mean, tex_p95 = texture_error(original, arrays(result),
                                                  np.random.default_rng(1))
                check = subprocess.run([sys.executable, str(CHECK), "check", str(source),
                                        str(path)], capture_output=True, text=True)
                share = check.stdout.split(", ")[1].split(" %")[0] if check.stdout else "-"
                rows.append(dict(
                    mesh=source.name, ratio=ratio, method=method, input_faces=faces,
                    target=target, faces=result.face_number(), seconds=round(seconds, 4),
                    hausdorff_max=round(100 * max(there["max"], back["max"]) / diagonal, 5),
                    hausdorff_mean=round(100 * max(there["mean"], back["mean"]) / diagonal, 5),
                    texture_mean=round(tex_mean, 6), texture_p95=round(tex_p95, 6),
                    corners_ok=share))
                print(rows[-1], flush=True)
    with open(out / "textured.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
