// Why vertices remain when a run stops short of its target: in words (Report::stop_detail)
// and as a cause (Report::stop_cause).
#pragma once

#include <array>
#include <cstddef>
#include <string>

#include "vrs/simplify.h"

namespace vrs {

// The remaining vertices by the first reason that keeps each.
struct Remaining {
  size_t boundary = 0;     // on the boundary and not removable there
  size_t corners = 0;      // removable boundary vertices never planned (outline corners)
  size_t constrained = 0;  // where seams or creases end, meet or cross
  size_t locked = 0;       // by the user
  size_t nonfinite = 0;    // a NaN/inf position, or next to one
  size_t split_seam = 0;   // border vertices at another's position (kFlagTwin)
  size_t nonmanifold = 0;  // non-manifold or inconsistently oriented
  size_t high_valence = 0; // more neighbours than the cap
  size_t untried = 0;      // no usable plane
  // Of the run's constrained edges, how many are seams of split vertices kept apart
  // (SplitVertices::Seam): where they are most, the words say how to weld them.
  size_t split_seam_edges = 0, constrained_edges = 0;
  std::array<size_t, RejectCount> refused{}; // by the veto that refused their last plan
};

// "remaining vertices: 12 on the boundary, ...; 3 refused by the vetoes (fold 2, flip 1)".
// `last_resort`: the run went through it (then fold-over refusals are said to be what stopped
// it).
std::string explain_remaining(const Remaining& r, bool simplify_boundary, bool last_resort);

// The group that keeps most of the remaining vertices (the first listed of equals).
StopCause main_cause(const Remaining& r);

} // namespace vrs
