"""Does the crease option (FeatureAngle) help on CAD meshes? Our filter in pymeshlab at 10 %
without and with a 40 degree feature angle, MeshLab's Hausdorff distance both ways.

    python bench/crease_compare.py PLUGIN OUT.csv MESH...
"""
import csv
import pathlib
import sys

import pymeshlab


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    pymeshlab.load_plugin(str(pathlib.Path(sys.argv[1]).resolve()))
    rows = []
    for mesh in map(pathlib.Path, sys.argv[3:]):
        for angle in (0.0, 40.0):
            ms = pymeshlab.MeshSet()
            ms.load_new_mesh(str(mesh))
            diagonal = ms.current_mesh().bounding_box().diagonal()
            faces = ms.current_mesh().face_number()
            ms.apply_filter("generate_copy_of_current_mesh")
            r = ms.apply_filter("meshing_decimation_vertex_removal", targetperc=0.1,
                                featureangle=angle)
            there = ms.get_hausdorff_distance(sampledmesh=1, targetmesh=0, samplenum=50000)
            back = ms.get_hausdorff_distance(sampledmesh=0, targetmesh=1, samplenum=50000)
            rows.append(dict(mesh=mesh.name, feature_angle=angle, input_faces=faces,
                             faces=ms.current_mesh().face_number(),
                             constrained_edges=r["constrained_edges"],
                             hausdorff_max=round(100 * max(there["max"], back["max"]) / diagonal, 5),
                             hausdorff_mean=round(100 * max(there["mean"], back["mean"]) / diagonal, 5)))
            print(rows[-1], flush=True)
    with open(sys.argv[2], "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
