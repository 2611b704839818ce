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
// survive its conversion): the report's keys of the CLI's JSON and the numpy API
// (docs/report.md), the groups flattened (rejected_<veto>, kept_<rule>), stop_reason as
// vrs::StopReason's number, summed over LOD levels, plus levels.
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
