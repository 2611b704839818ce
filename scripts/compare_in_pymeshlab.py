"""Our filter beside MeshLab's Quadric Edge Collapse Decimation in pymeshlab: the same mesh, the
same target, MeshLab's own Hausdorff distance both ways, times, and the output files.

    python scripts/compare_in_pymeshlab.py PLUGIN MESH [RATIO] [OUT_DIR]

PLUGIN is the build for pymeshlab (build/pymeshlab/plugins/libfilter_vertex_removal.so).
Times are the best of 3 runs, each on a fresh copy of the mesh, as the filters report them
to Python (wall clock around apply_filter).
"""
import importlib.metadata
import pathlib
import sys
import time

import pymeshlab

METHODS = {
    "Vertex Removal Decimation (ours)": ("ours", "meshing_decimation_vertex_removal", {}),
    "Quadric Edge Collapse Decimation": ("qecd", "meshing_decimation_quadric_edge_collapse", {}),
}
SAMPLES = 100000


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    plugin, mesh = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve()
    ratio = float(sys.argv[3]) if len(sys.argv) > 3 else 0.1
    out = pathlib.Path(sys.argv[4] if len(sys.argv) > 4 else "out").resolve()
    out.mkdir(parents=True, exist_ok=True)
    pymeshlab.load_plugin(str(plugin))

    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(mesh))  # layer 0: the original
    faces = ms.current_mesh().face_number()
    diagonal = ms.current_mesh().bounding_box().diagonal()
    target = round(faces * ratio)
    print(f"{mesh.name}: {faces} faces -> target {target} ({ratio:g}), "
          f"pymeshlab {importlib.metadata.version('pymeshlab')}")

    rows = []
    for label, (short, name, extra) in METHODS.items():
        best = float("inf")
        for _ in range(3):
            ms.set_current_mesh(0)
            ms.apply_filter("generate_copy_of_current_mesh")
            start = time.perf_counter()
            ms.apply_filter(name, targetfacenum=target, **extra)
            best = min(best, time.perf_counter() - start)
            layer = ms.current_mesh_id()
        result_faces = ms.current_mesh().face_number()
        path = out / f"{mesh.stem}-{short}.ply"
        ms.save_current_mesh(str(path))
        there = ms.get_hausdorff_distance(sampledmesh=layer, targetmesh=0, samplenum=SAMPLES)
        back = ms.get_hausdorff_distance(sampledmesh=0, targetmesh=layer, samplenum=SAMPLES)
        rows.append((label, result_faces, best, 100 * max(there["max"], back["max"]) / diagonal,
                     100 * max(there["mean"], back["mean"]) / diagonal, path))

    print()
    print("| method | faces | time (s) | Hausdorff max (% diag) | Hausdorff mean (% diag) |")
    print("|---|---|---|---|---|")
    for label, result_faces, seconds, hmax, hmean, _ in rows:
        print(f"| {label} | {result_faces} | {seconds:.3f} | {hmax:.4f} | {hmean:.4f} |")
    print(f"\nMeshLab's Hausdorff Distance filter, symmetric, {SAMPLES} samples a side.")
    for *_, path in rows:
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
