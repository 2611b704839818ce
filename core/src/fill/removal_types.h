// Shared vocabulary of the planning pieces (candidates, vetoes, removal).
#pragma once

#include <cstdint>

namespace vrs {

// What an open ring is. Border: v is on the mesh's border; the closing edge (last, first) is
// a new border edge and v must be a convex corner (cutting a reflex one would add area outside
// the mesh). SeamSide: one side of a constrained polyline through v (see Planner::plan_seam);
// the other side gives up or takes the area between the polyline and the chord, so v may be
// reflex. SeamSideOnEdge: the same, when the chord is already an edge of the mesh (the other
// side is one triangle, which simply goes).
enum class OpenRing : uint8_t { Border, SeamSide, SeamSideOnEdge };

} // namespace vrs
