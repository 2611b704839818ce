// Coherent orientation: meshes whose faces were written in random order of corners (shuffled
// exports, some scanners' output) are manifold surfaces all the same; only the order of their
// faces' corners disagrees. The driver orients them before anything else reads the fans.
#pragma once

#include <cstdint>
#include <vector>

#include "base/workers.h"
#include "mesh/topology.h"

namespace vrs {

// Reverses faces (corners 1 and 2 swapped) so that the two faces of every edge held by exactly
// two faces walk it in opposite directions, in each connected piece that is orientable (others
// stay as given); in
// each piece the orientation most of its faces had is kept (on a tie, that of its face of
// lowest `rank`: the caller's numbering, so the choice does not depend on the faces' order).
// `flipped[f]` is set for each face reversed (sized to the face count when something is).
// Returns the number reversed. `topo` holds the faces' vertex lists (a reversal keeps them).
// The first look (is anything to do?) runs on `workers` when given.
size_t orient_coherently(std::vector<uint32_t>& tris, const Topology& topo, const uint32_t* rank,
                         std::vector<uint8_t>& flipped, Workers* workers = nullptr);

// Pieces written in different orientations and welded along their seams (split_vertices.h)
// were turned by orient_coherently (`flipped`, on the welded `tris` and `topo`; empty: none)
// where the pieces apart would not have been, or the other way: `apart` holds the same faces
// unwelded, as given. Returns the faces so turned, to be given back on output (a shuffled
// piece's faces stay turned, as without the weld), and the edges between them and the others
// (pairs): kept, so that no face spans two orientations.
struct TurnedByWelding {
  std::vector<uint8_t> faces; // per face slot; empty: none
  std::vector<uint32_t> edges;
};
TurnedByWelding turned_by_welding(const std::vector<uint32_t>& tris, const Topology& topo,
                                  const std::vector<uint8_t>& flipped, std::vector<uint32_t> apart,
                                  const uint32_t* rank, Workers* workers);

} // namespace vrs
