// The filter's parameters: their declaration for the dialog and .mlx scripts (names are
// permanent: scripts and pymeshlab's lowercased names are built from them), their validation,
// and the core options they mean for one layer.
#pragma once

#include "meshlab_compat.h"

#include <QString>

#include "vrs/simplify.h"

namespace vrs_plugin {

struct FilterSettings {
  // What the user asked, validated.
  int target_faces = 0; // for the first level, after TargetPerc and Selected are applied
  int target_vertices = 0;
  double max_factor = 0;
  bool auto_stop = false;
  vrs::Mode mode = vrs::Mode::Surface3D;
  vrs::Priority priority = vrs::Priority::LocalError; // dialog: 0 local error, 1 factor
  int intervals = 1000;
  bool preserve_boundary = true;
  bool selected = false;
  bool auto_clean = true;
  int lod_levels = 1;
  double feature_angle = 0; // degrees, 0 = off (2022+ hosts only, see meshlab_compat.h)
  double max_error = 0;     // % of the bounding-box diagonal, 0 = off (2022+ hosts only)
  // Size of the input layer, to carry "the same reduction" to the next LOD levels.
  int input_faces = 0, input_vertices = 0;

  // Core options for a layer of the given size at LOD level `level` (1 = from the input).
  vrs::Options options_for(int level, int faces, int vertices) const;
};

void declare_parameters(const MeshModel& m, RichParameterList& par);

// Fills `out` and returns "" or a message for the user naming the bad parameter.
QString read_parameters(const RichParameterList& par, const CMeshO& m, FilterSettings& out);

} // namespace vrs_plugin
