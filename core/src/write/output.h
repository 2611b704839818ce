// The run's result in the caller's terms: the surviving vertices and faces back in the input's
// order, with what each output element came from, and the input's problems in words.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/workers.h"
#include "mesh/constraints.h"
#include "mesh/spatial_order.h"
#include "vrs/simplify.h"

namespace vrs {

// What the run kept per face slot (internal order; its input slot and whether it was rewritten
// are SpatialOrder::face_old's): the input face of each input slot (empty: the slot's own),
// the input corner each corner carries (empty: not asked), the certified bound (empty: none).
struct SlotRecords {
  const UninitVector<uint32_t>& kept_faces;
  const std::vector<uint32_t>& corner_source;
  const std::vector<float>& face_bound;
  // Split vertices welded for the run (split_vertices.h; empty: none): each input corner's
  // own copy, and the copy standing for each input vertex. Corners then need corner_source.
  const std::vector<uint32_t>& corners;
  const std::vector<uint32_t>& standing;
  // Per input face, nonzero: turned over for the run, written back the other way (empty:
  // none). An output face takes its first corner's (corner_source; its corners all come from
  // one side of the constrained edges, and the edges between orientations are).
  const std::vector<uint8_t>& turned;
  // Whether an edge (internal numbering) is constrained, for Report::constrained_sides (null:
  // not asked).
  const Constraints* constraints = nullptr;
};

// Rewrites `mesh` (internal order, dead slots holding kNone) as its live part in the input's
// order: vertices by input index (`removed[v]` nonzero: gone), faces by the input slot they
// took. Fills rep's remap, face_source, corner_source, error_bound, faces and vertices. On the
// workers when given (the same output on any number).
void write_output(Mesh& mesh, const SpatialOrder& order, const std::vector<uint8_t>& removed,
                  const SlotRecords& records, Report& rep, Workers* workers = nullptr);

// The input's problems the run worked around ("3 faces with a repeated vertex dropped; ...").
std::string input_warnings(const Report& r);

} // namespace vrs
