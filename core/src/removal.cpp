#include "removal.h"

#include <algorithm>

namespace vrs {

namespace {

// Is (a, b) an edge of the ring's polygon that already exists in the mesh? For an open ring the
// closing edge (last, first) is new unless `closing_exists`.
bool is_ring_edge(const Ring& ring, int a, int b, bool closing_exists) {
  int k = ring.verts;
  bool closed = ring.closed() || closing_exists;
  if ((a + 1) % k == b && (closed || a + 1 < k)) return true;
  if ((b + 1) % k == a && (closed || b + 1 < k)) return true;
  return false;
}

// The ring's positions and their projections on the plane of `n`, relative to v.
void project(uint32_t v, const Ring& ring, Vec3 n, const Evaluator& eval, Patch& out) {
  plane_basis(n, out.u, out.w);
  const Vec3 c = eval.position(v);
  for (int i = 0; i < ring.verts; ++i) {
    out.q[i] = eval.position(ring.v[i]);
    Vec3 d = out.q[i] - c;
    out.p[i] = {dot(d, out.u), dot(d, out.w)};
  }
  out.normal = n;
}

} // namespace

bool star_direction(uint32_t v, const Ring& ring, const Evaluator& eval, Vec3& out) {
  const int k = ring.verts;
  const Vec3 c = eval.position(v);
  std::array<Vec3, kMaxRing> n;
  Vec3 area, unit;
  for (int i = 0; i < ring.faces; ++i) {
    Vec3 a = cross(eval.position(ring.v[i]) - c, eval.position(ring.v[(i + 1) % k]) - c);
    n[i] = normalized(a);
    area = area + a;
    unit = unit + n[i];
  }
  auto sees_star = [&](Vec3 d) {
    if (!(length(d) > 0)) return false;
    for (int i = 0; i < ring.faces; ++i)
      if (!(dot(n[i], d) > 1e-6)) return false;
    return true;
  };
  for (Vec3 d : {normalized(area), normalized(unit)})
    if (sees_star(d)) {
      out = d;
      return true;
    }
  for (int i = 0; i < ring.faces; ++i)
    if (sees_star(n[i])) {
      out = n[i];
      return true;
    }
  return false;
}

Reject plan_removal(uint32_t v, const Ring& ring, Vec3 n, const Evaluator& eval,
                    const Topology& topo, const uint32_t* tris, const float* surface_normals,
                    const RemovalLimits& limits, Patch& out, bool check_topology, OpenRing open) {
  const int k = ring.verts;
  if (k < 3) return RejectFold;
  project(v, ring, n, eval, out); // the plan keeps them for patch_error
  const auto& q = out.q;
  const auto& p = out.p;
  const Vec2 o{0, 0};

  // The old fan must project without folds: the ring is then a star-shaped simple polygon
  // around the vertex and any triangulation of it covers the same region.
  for (int i = 0; i < ring.faces; ++i)
    if (!(orient2d(o, p[i], p[(i + 1) % k]) > 0)) return RejectFold;
  if (!ring.closed()) {
    // Open fan: cutting the vertex off must leave a simple polygon. At a convex corner the
    // chain must lie beyond the chord; at a reflex one (seams only) the chord lies in the
    // other side's wedge and cannot meet the chain, which is star-shaped around the vertex.
    const bool convex = orient2d(p[k - 1], o, p[0]) >= 0; // straight is fine
    if (!convex && open == OpenRing::Border) return RejectFold;
    for (int j = 1; j + 1 < k && convex; ++j)
      if (!(orient2d(p[k - 1], p[0], p[j]) > 0)) return RejectFold;
  }

  if (ring.closed() && is_convex(p.data(), k)) {
    triangulate_fan(p.data(), q.data(), n, k, out);
  } else if (!triangulate_ears(p.data(), q.data(), n, k, out)) {
    return RejectFold;
  }

  for (int t = 0; t < out.count; ++t)
    for (int c = 0; c < 3; ++c)
      out.from[t][c] = static_cast<uint8_t>(std::min(int(out.tri[t][c]), ring.faces - 1));
  // Topology first (it cannot change with the projection), then shape.
  for (int t = 0; t < out.count && check_topology; ++t) {
    const auto& tri = out.tri[t];
    if (topo.has_triangle(ring.v[tri[0]], ring.v[tri[1]], ring.v[tri[2]], tris))
      return RejectTriangle;
    for (int e = 0; e < 3; ++e) {
      int a = tri[e], b = tri[(e + 1) % 3];
      if (!is_ring_edge(ring, a, b, open == OpenRing::SeamSideOnEdge) &&
          topo.has_edge(ring.v[a], ring.v[b], tris))
        return RejectEdge;
    }
  }
  for (int t = 0; t < out.count; ++t) {
    const auto& tri = out.tri[t];
    Vec3 a = q[tri[0]], b = q[tri[1]], d = q[tri[2]];
    if (triangle_quality(a, b, d) < limits.min_quality) return RejectDegenerate;
    Vec3 face = normalized(cross(b - a, d - a));
    if (dot(face, n) < limits.min_normal_cos) return RejectFlip;
    Vec3 original;
    for (int c = 0; c < 3; ++c) {
      const float* sn = surface_normals + 3 * size_t(ring.v[tri[c]]);
      original = original + Vec3{sn[0], sn[1], sn[2]};
    }
    if (!(dot(face, original) > 0)) return RejectFlip;
  }
  return RejectCount;
}

Reject plan_seam_removal(uint32_t v, const Ring& ring, int i, int j, Vec3 n, const Evaluator& eval,
                         const Topology& topo, const uint32_t* tris, const float* surface_normals,
                         const RemovalLimits& limits, Patch& out, bool check_topology) {
  const int k = ring.verts;
  // Two faces back to back (a fin: both sides one triangle) have no side left to fill.
  if (k < 3) return RejectFold;
  Patch side;
  int count = 0;
  // Side 0 runs from ring[i] to ring[j] counter-clockwise, side 1 from ring[j] back to ring[i].
  for (int s = 0; s < 2; ++s) {
    const int first = s == 0 ? i : j, m = (s == 0 ? j - i : k - j + i) + 1;
    if (m < 3) continue; // one triangle on this side: it goes, the chord is its ring edge
    const bool on_edge = (s == 0 ? k - j + i : j - i) == 1;
    Ring sub;
    sub.verts = m;
    sub.faces = m - 1;
    for (int r = 0; r < m; ++r)
      sub.v[r] = ring.v[(first + r) % k];
    for (int r = 0; r + 1 < m; ++r)
      sub.f[r] = ring.f[(first + r) % k];
    Reject why =
        plan_removal(v, sub, n, eval, topo, tris, surface_normals, limits, side, check_topology,
                     on_edge ? OpenRing::SeamSideOnEdge : OpenRing::SeamSide);
    if (why != RejectCount) return why;
    for (int t = 0; t < side.count; ++t, ++count)
      for (int c = 0; c < 3; ++c) {
        out.tri[count][c] = static_cast<uint8_t>((first + side.tri[t][c]) % k);
        out.from[count][c] = static_cast<uint8_t>((first + side.from[t][c]) % k);
      }
  }
  out.count = count;
  project(v, ring, n, eval, out);
  return RejectCount;
}

} // namespace vrs
