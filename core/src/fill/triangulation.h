// Fills the hole a removed vertex leaves (paper §2.4): the ring, projected on the plane, is a
// simple counter-clockwise polygon; convex ones get a fan, others ear clipping.
#pragma once

#include <array>
#include <cstdint>

#include "base/geometry.h"
#include "mesh/topology.h"

namespace vrs {

struct Patch {
  int count = 0;
  std::array<std::array<uint8_t, 3>, kMaxRing> tri; // indices into the ring, counter-clockwise
  // For each new corner, the ring face (index into Ring::f) it takes its per-corner data from:
  // an old face at the same vertex, on the same side of any constrained edge.
  std::array<std::array<uint8_t, 3>, kMaxRing> from;
  // The ring as it was planned (filled by the Planner, read by patch_error): the direction
  // it was projected along with its plane basis (u, w), the ring's 3D positions and their
  // projections relative to the removed vertex.
  Vec3 normal, u, w;
  UnsetArray<Vec3, kMaxRing + 1> q;
  UnsetArray<Vec2, kMaxRing + 1> p;
  // The faces the patch replaces, ring face i = (removed vertex, ring[i], ring[i + 1]): unit
  // normals and areas, made once with the projection (set_replaced_faces) for the shape
  // veto, the price and the accounting, which each made them before.
  UnsetArray<Vec3, kMaxRing> face_n;
  UnsetArray<double, kMaxRing> face_area;
  // With an error bound tracked (error_bound.h): each new triangle's certified bound.
  std::array<float, kMaxRing> bound;
  // Set by the shape veto (vetoes.h): why some corner's input normal cannot vouch for its new
  // triangle (UnsureCorner bits). Then the planner asks the input itself; on a crease the price
  // counts the surface moved too (patch_error).
  uint8_t unsure_corners = 0;
  // The candidate (candidates.h) that made it, as a hint for the same ring's next plan
  // (Planner::plan); kNoCandidate: the least-cost filling, a seam's sides, or one ranked after a
  // candidate the mesh's other faces refused.
  uint8_t candidate = 0;
};
constexpr uint8_t kNoCandidate = 255;

enum UnsureCorner : uint8_t {
  kCornerTurned = 1,   // its normal more than 45 degrees from the triangle
  kCornerOnCrease = 2, // its input faces spread more than 30 degrees: a crease, a rim, a thin wall
};

bool is_convex(const Vec2* p, int k);

// Patch::face_n and face_area of the ring's faces around the removed vertex at c (the ring's
// positions in `patch.q`).
void set_replaced_faces(Vec3 c, const Ring& ring, Patch& patch);

// The new triangle whose projection on the plan's plane holds s (relative to the removed
// vertex), or -1 when s lies outside the patch.
int triangle_under(const Patch& patch, Vec2 s);

// Score of a new triangle (a, b, c) in 3D: its shape quality times how squarely it faces the
// projection normal n. Shape alone would happily pick a well-shaped triangle standing across
// the surface (a chord through the solid); facing n keeps the patch on the surface.
// Inline: the fans' and ears' inner loops call it for every triangle they weigh.
// quality * facing = (2√3 |x| / Σe²) * (x·n / |x|) with x = (b-a)×(c-a): no square root.
// `facing` = x·n, `sum` = Σe² (|b-a|² + |c-b|² + |a-c|², in that order).
inline double score_of(double facing, double sum) {
  return facing > 0 && sum > 0 ? 3.4641016151377544 * facing / sum : 0.0;
}
inline double triangle_score(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n) {
  return score_of(dot(cross(b - a, c - a), n),
                  dot(b - a, b - a) + dot(c - b, c - b) + dot(a - c, a - c));
}

// Fan from the apex whose worst triangle scores best (3D positions `q`, projection normal n).
void triangulate_fan(const Vec2* p, const Vec3* q, Vec3 n, int k, Patch& out);

// Ear clipping that always cuts the best-scoring valid ear, so slivers and steep triangles are
// made only when nothing else fits. False if the polygon has no valid ear (not simple).
bool triangulate_ears(const Vec2* p, const Vec3* q, Vec3 n, int k, Patch& out);

} // namespace vrs
