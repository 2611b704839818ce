// Plans the removal of one vertex: projects its ring on the plane, triangulates the hole and
// runs the vetoes. Nothing is written; the driver commits an accepted plan.
#pragma once

#include "evaluation.h"
#include "topology.h"
#include "triangulation.h"
#include "vrs/simplify.h"

namespace vrs {

struct RemovalLimits {
  double min_normal_cos = 0.17; // cos(max_normal_angle_deg)
  // Quality (1 = equilateral) under which a new triangle counts as degenerate. Low on purpose:
  // thin triangles are legitimate on CAD meshes; only near-zero-area ones are refused.
  double min_quality = 1e-3;
};

// A direction on which every triangle around v projects counter-clockwise, tried among the
// fan's area-weighted normal, the mean of its unit normals and each triangle's own normal.
bool star_direction(uint32_t v, const Ring& ring, const Evaluator& eval, Vec3& out);

// What an open ring is. Border: v is on the mesh's border; the closing edge (last, first) is
// a new border edge and v must be a convex corner (cutting a reflex one would add area outside
// the mesh). SeamSide: one side of a constrained polyline through v (see plan_seam_removal);
// the other side gives up or takes the area between the polyline and the chord, so v may be
// reflex. SeamSideOnEdge: the same, when the chord is already an edge of the mesh (the other
// side is one triangle, which simply goes).
enum class OpenRing : uint8_t { Border, SeamSide, SeamSideOnEdge };

// Returns RejectCount when the removal is valid (the patch is in `out`), else the reason.
// `check_topology` = false skips the two mesh look-ups (new triangle / diagonal already
// there): a planning-only pass for the priority, redone in full when the vertex is popped.
// `surface_normals` holds the input's unit vertex normals (3 floats a vertex): a new triangle
// must face the same side as the original surface at its corners, which the local plane alone
// cannot promise after many removals have moved the ring.
Reject plan_removal(uint32_t v, const Ring& ring, Vec3 normal, const Evaluator& eval,
                    const Topology& topo, const uint32_t* tris, const float* surface_normals,
                    const RemovalLimits& limits, Patch& out, bool check_topology = true,
                    OpenRing open = OpenRing::Border);

// The removal of a vertex on exactly two constrained edges, to ring positions i < j: the ring
// is cut along the polyline (ring[i], v, ring[j]) and each side is planned as an open ring
// closed by the chord (ring[i], ring[j]), which replaces the two constrained edges. Both sides
// are projected along `normal`; `out` is a patch of the whole ring, as plan_removal's.
Reject plan_seam_removal(uint32_t v, const Ring& ring, int i, int j, Vec3 normal,
                         const Evaluator& eval, const Topology& topo, const uint32_t* tris,
                         const float* surface_normals, const RemovalLimits& limits, Patch& out,
                         bool check_topology = true);

} // namespace vrs
