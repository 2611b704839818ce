"""Vertex Removal Decimation from a pymeshlab script (pymeshlab 2025.7).

    python pymeshlab_example.py IN_MESH OUT_MESH [PLUGIN]

PLUGIN is the build for pymeshlab (build/pymeshlab/plugins/libfilter_vertex_removal.so); leave
it out once `cmake --install build --component pymeshlab` has put it into pymeshlab's own
plugins folder, where pymeshlab loads it by itself.
"""
import sys

import pymeshlab

STOP_REASONS = ("target reached", "max priority", "last interval", "no removable vertex left",
                "cancelled")

source, destination = sys.argv[1:3]
if len(sys.argv) > 3:
    pymeshlab.load_plugin(sys.argv[3])  # once per process
ms = pymeshlab.MeshSet()
ms.load_new_mesh(source)
# Parameters are the filter dialog's, lowercased: targetfacenum, targetperc, targetvertnum,
# maxfactor, autostop, mode, priority, intervals, preserveboundary, selected, autoclean, lodlevels.
result = ms.apply_filter("meshing_decimation_vertex_removal", targetperc=0.1, preserveboundary=True)
print(f"{result['input_faces']} -> {result['output_faces']} faces in {result['seconds_simplify']:.3f} s, "
      f"stopped: {STOP_REASONS[result['stop_reason']]}")
ms.save_current_mesh(destination)
