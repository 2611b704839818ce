// The ways to fill the hole a removed vertex leaves. Each candidate writes the triangles of a
// patch over the ring (indices into it); whether it is allowed is the vetoes' business
// (vetoes.h), what it costs the priority's. Kept apart so a new filling is one new function.
#pragma once

#include "removal_types.h"
#include "topology.h"
#include "triangulation.h"

namespace vrs {

// Candidate 0 is the paper's: the ring projected on the evaluated plane and triangulated
// there. Candidates 1..k are the fans from ring vertex apex = candidate - 1: exactly a
// half-edge collapse of the vertex onto that neighbour, which needs no projection (it still
// works where the ring folds on every plane: tips, creases, thin parts).
// A three-vertex ring has one triangle whatever the apex: one fan stands for all. A vertex of
// a single triangle (an open two-vertex ring) has one filling: none, the triangle goes.
inline int candidate_count(const Ring& ring, bool fans) {
  return fans && ring.verts > 2 ? 1 + (ring.verts == 3 ? 1 : ring.verts) : 1;
}

// Writes candidate `c` into `out` (tri and from; the projection `out.p`, `out.q` and
// `out.normal` must be set). False when the projection folds (candidate 0 only).
bool fill_candidate(const Ring& ring, OpenRing open, int c, Patch& out);

// Sets `out.from` for its triangles (the ring face each new corner takes its data from).
void set_corner_faces(const Ring& ring, Patch& out);

} // namespace vrs
