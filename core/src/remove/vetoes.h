// What forbids a planned patch. Each veto names its reason (Reject); the planner tries the
// next candidate when one is refused.
#pragma once

#include <limits>

#include "evaluate/evaluation.h"
#include "fill/removal_types.h"
#include "fill/triangulation.h"
#include "mesh/topology.h"
#include "vrs/simplify.h"

namespace vrs {

struct RemovalLimits {
  double min_normal_cos = 0.17; // cos(max_normal_angle_deg)
  // Quality (1 = equilateral) under which a new triangle counts as degenerate. Low on purpose:
  // thin triangles are legitimate on CAD meshes; only near-zero-area ones are refused.
  double min_quality = 1e-3;
  // A new triangle whose normal makes more than 90° with a face it replaces folds the
  // surface over onto itself.
  double min_fold_cos = 0.0;
  // A new triangle must also face the input surface's side at this many of its corners (the
  // input's vertex normals). After many removals its corners can be far apart on a curved
  // part, so the driver's last resort, when nothing else is left to remove and the target is
  // not met, asks it of one corner only (the fold-over veto stays).
  int agreeing_corners = 3;
  // The last resort's filling too (candidates.h, fill_least_cost), where every other one is
  // refused: the triangulation of the ring whose triangles stand nearest the old fan, of those
  // no veto refuses triangle by triangle.
  bool least_cost_filling = false;
  // In the eased passes the input's nearest faces judge every new triangle (InputSurface::folds,
  // the fold-over as the benchmark measures it); the faces a patch replaces then no longer
  // refuse it for turning over them. By then they can be slivers whose normals stand for
  // nothing: a thread's groove wall, under a ridge leaning over the core, refused every filling
  // of the ridge's vertices, and the threaded parts stopped at twice their target.
  bool folds_judged_by_input = false;
  // New triangles at least this large (area) are asked against the input's nearest faces in
  // every pass, their corners sure or not, and a patch whose such triangles fold over more
  // than `fold_budget` of area is refused: on an output of a few hundred faces one folded
  // triangle is a percent of the area, and corners far apart by then vouch for little. Shares
  // of the input's area (setup), so that a large run's triangles never reach them.
  double large_triangle_area = std::numeric_limits<double>::infinity();
  double fold_budget = std::numeric_limits<double>::infinity();
  // With an error bound tracked (Options::max_error): no new face's certified bound above it.
  double max_error = std::numeric_limits<double>::infinity();
};

// Manifold topology: no new triangle that already exists, no new edge that already exists
// (it would get a third face); a triangle cut off leaves its outer edge to another face.
Reject veto_topology(const Ring& ring, const Patch& patch, OpenRing open, const Topology& topo,
                     const uint32_t* tris);

// Shape: no sliver, no triangle facing against the input surface at its corners
// (`surface_normals`: 4 floats a vertex, the unit normal and the sine of its faces' spread about
// it; see limits.agreeing_corners), none turned over against the face(s) it replaces, and, when
// `plane_angle` (fillings made on the projection plane), none steeper than limits.min_normal_cos
// to that plane.
// `replaced`: the unit normals of the faces the patch replaces (a plan's Patch::face_n, the same
// for every candidate of one plan); not read once limits.folds_judged_by_input.
// `unsure` (when given, of a patch no veto refuses): the UnsureCorner bits of corners that cannot
// vouch for their triangle, their normal more than 45 degrees from it or their faces spreading
// more than 30 degrees about them (a crease, a rim, a thin wall): there the planner asks the
// input itself. Told here, where the corners are compared anyway, not by a second pass.
using FaceNormals = UnsetArray<Vec3, kMaxRing>;
Reject veto_shape(const Ring& ring, const Patch& patch, const FaceNormals& replaced,
                  const float* surface_normals, const RemovalLimits& limits, bool plane_angle,
                  uint8_t* unsure = nullptr);

// veto_shape for one new triangle (ring positions `tri`, counter-clockwise).
Reject veto_triangle(const Ring& ring, const Patch& patch, std::array<uint8_t, 3> tri,
                     const FaceNormals& replaced, const float* surface_normals,
                     const RemovalLimits& limits, bool plane_angle, uint8_t* unsure = nullptr);

// Error bound (error_bound.h): the patch must project one-to-one with the fan it replaces, and
// every new face's certified bound (written into patch.bound) must stay within
// limits.max_error. `face_bound`: each face slot's bound; `c`: the removed vertex's position.
Reject veto_bound(const Ring& ring, Patch& patch, Vec3 c, const float* face_bound,
                  const RemovalLimits& limits);

} // namespace vrs
