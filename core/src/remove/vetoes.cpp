#include "remove/vetoes.h"

#include <utility>

#include "evaluate/error_bound.h"

namespace vrs {

namespace {

// Is (a, b) an edge of the ring's polygon that already exists in the mesh? For an open ring the
// closing edge (last, first) is new unless `closing_exists`.
bool is_ring_edge(const Ring& ring, int a, int b, bool closing_exists) {
  int k = ring.verts;
  bool closed = ring.closed() || closing_exists;
  if (wrap(a + 1, k) == b && (closed || a + 1 < k)) return true;
  if (wrap(b + 1, k) == a && (closed || b + 1 < k)) return true;
  return false;
}

} // namespace

Reject veto_topology(const Ring& ring, const Patch& patch, OpenRing open, const Topology& topo,
                     const uint32_t* tris) {
  // A triangle cut off the outline must leave its third edge to another face: alone, the
  // triangle is a whole component, and it would vanish.
  if (ring.verts == 2 && topo.edge_faces(ring.v[0], ring.v[1], tris) < 2) return RejectEdge;
  // A triangle with a new edge can only exist if that edge does: the mesh look-up for the
  // triangle is needed only then (to name the refusal) or when all its edges are ring edges.
  // Each diagonal is looked up once although two triangles share it.
  std::array<uint64_t, kMaxRing + 1> absent{}; // bit b of absent[a], a < b < 64: not an edge
  for (int t = 0; t < patch.count; ++t) {
    const auto& tri = patch.tri[t];
    const uint32_t x = ring.v[tri[0]], y = ring.v[tri[1]], z = ring.v[tri[2]];
    bool has_new_edge = false;
    for (int e = 0; e < 3; ++e) {
      int a = tri[e], b = tri[(e + 1) % 3];
      if (is_ring_edge(ring, a, b, open == OpenRing::SeamSideOnEdge)) continue;
      has_new_edge = true;
      if (a > b) std::swap(a, b);
      if (b < 64 && absent[a] >> b & 1) continue;
      if (topo.has_edge(ring.v[a], ring.v[b], tris))
        return topo.has_triangle(x, y, z, tris) ? RejectTriangle : RejectEdge;
      if (b < 64) absent[a] |= uint64_t(1) << b;
    }
    if (!has_new_edge && topo.has_triangle(x, y, z, tris)) return RejectTriangle;
  }
  return RejectCount;
}

Reject veto_triangle(const Ring& ring, const Patch& patch, std::array<uint8_t, 3> tri,
                     const FaceNormals& old_n, const float* surface_normals,
                     const RemovalLimits& limits, bool plane_angle, uint8_t* unsure) {
  constexpr double kSureCos = 0.7, kCreaseSpreadSin = 0.5;
  const int k = ring.verts;
  const auto& q = patch.q;
  auto folds_on = [&](Vec3 face, int i) { return !(dot(face, old_n[i]) > limits.min_fold_cos); };
  Vec3 a = q[tri[0]], b = q[tri[1]], d = q[tri[2]];
  if (triangle_quality(a, b, d) < limits.min_quality) return RejectDegenerate;
  Vec3 face = normalized(cross(b - a, d - a));
  if (plane_angle && dot(face, patch.normal) < limits.min_normal_cos) return RejectFlip;
  int agreeing = 0;
  for (int e = 0; e < 3; ++e) {
    const float* sn = surface_normals + 4 * size_t(ring.v[tri[e]]);
    const double d = dot(face, Vec3{sn[0], sn[1], sn[2]});
    agreeing += d > 0;
    if (unsure && !(d >= kSureCos)) *unsure |= kCornerTurned;
    if (unsure && sn[3] > kCreaseSpreadSin) *unsure |= kCornerOnCrease;
  }
  if (agreeing < limits.agreeing_corners) return RejectFlip;
  if (limits.folds_judged_by_input) return RejectCount;
  // The faces it replaces: the old face on each of its ring edges; a triangle made of
  // diagonals only answers to the old faces at its corners.
  bool on_ring_edge = false;
  for (int e = 0; e < 3; ++e) {
    int i = tri[e], j = tri[(e + 1) % 3];
    if (j == wrap(i + 1, k) && i < ring.faces) {
      on_ring_edge = true;
      if (folds_on(face, i)) return RejectFoldOver;
    }
  }
  if (!on_ring_edge)
    for (int e = 0; e < 3; ++e) {
      int i = tri[e];
      if (i < ring.faces && folds_on(face, i)) return RejectFoldOver;
      int before = i > 0 ? i - 1 : ring.closed() ? k - 1 : -1;
      if (before >= 0 && folds_on(face, before)) return RejectFoldOver;
    }
  return RejectCount;
}

Reject veto_shape(const Ring& ring, const Patch& patch, const FaceNormals& old_n,
                  const float* surface_normals, const RemovalLimits& limits, bool plane_angle,
                  uint8_t* unsure) {
  for (int t = 0; t < patch.count; ++t) {
    const Reject why = veto_triangle(ring, patch, patch.tri[t], old_n, surface_normals, limits,
                                     plane_angle, unsure);
    if (why != RejectCount) return why;
  }
  return RejectCount;
}

Reject veto_bound(const Ring& ring, Patch& patch, Vec3 c, const float* face_bound,
                  const RemovalLimits& limits) {
  if (!bound_patch(ring, patch, c, face_bound)) return RejectBound;
  for (int t = 0; t < patch.count; ++t)
    if (!(patch.bound[t] <= limits.max_error)) return RejectBound;
  return RejectCount;
}

} // namespace vrs
