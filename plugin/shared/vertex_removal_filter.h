// The filter "Simplification: Vertex Removal Decimation", written once for every MeshLab: its
// names, its description, and one application (parameters in, the core run on each layer, the
// log lines and the result values out). The per-version adapters (meshlab2020/, meshlab2022/)
// only turn this into their host's entry points and error protocol.
#pragma once

#include "meshlab_compat.h"

#include <QString>
#include <QVariant>

#include <functional>
#include <map>
#include <string>

namespace vrs_plugin {

// Names users see; scripts depend on them, so they never change.
QString filter_name();        // GUI and .mlx name
QString python_filter_name(); // pymeshlab: as MeshLab's meshing_decimation_quadric_edge_collapse
QString filter_info();        // the dialog's help text

// What the host gives an application.
struct Host {
  std::function<void(GLLogStream::Levels, const QString&)> log;
  vcg::CallBackPos* progress = nullptr; // may be null (pymeshlab)
};

// The values a run hands back (pymeshlab returns them as a dict; only numbers and booleans
// survive its conversion): input_faces, input_vertices, output_faces, output_vertices,
// removed_vertices, levels, stop_reason (vrs::StopReason as a number: 0 target reached, 1 max
// priority, 2 last interval, 3 no candidates left, 4 cancelled), target_reached,
// rejected_removals and rejected_<reason> for each vrs::Reject, kept_boundary,
// kept_nonmanifold, kept_locked, kept_high_valence, kept_constrained (vertices kept by seams
// and creases) (summed over LOD levels), constrained_edges (seam and crease edges of the
// input), max_priority (the
// largest priority of a removed vertex, mesh units), seconds (core time).
using FilterResult = std::map<std::string, QVariant>;

struct Outcome {
  bool ok = false;
  QString error;       // when !ok: for the user; the document is as it was before the call
  FilterResult result; // when ok
};

// Applies the filter to the current layer of `md` (or to new LOD layers). Never throws: any
// failure, an exception included, comes back as an error with the document unchanged.
Outcome apply_vertex_removal(MeshDocument& md, const RichParameterList& par, const Host& host);

} // namespace vrs_plugin
