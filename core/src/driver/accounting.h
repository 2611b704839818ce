// What a committed removal changes beyond its faces: the counts, a seam's polyline, and the
// neighbours' prices (marked stale and moved by their fans' new area, or priced again).
#pragma once

#include <array>

#include "base/geometry.h"
#include "fill/triangulation.h"
#include "mesh/topology.h"

namespace vrs {

// How a removal changes the area of the faces around each ring vertex i: its faces i - 1 and i
// (`patch.face_area`) are replaced by the patch's triangles at i (`patch.q`: the ring's
// positions).
void fan_area_changes(const Ring& ring, const Patch& patch,
                      std::array<double, kMaxRing + 1>& change);

} // namespace vrs
