#include "removal.h"

namespace vrs {

namespace {

// Is (a, b) an edge of the ring's polygon that already exists in the mesh? For an open ring the
// closing edge (last, first) is new.
bool is_ring_edge(const Ring& ring, int a, int b) {
  int k = ring.verts;
  if ((a + 1) % k == b && (ring.closed() || a + 1 < k)) return true;
  if ((b + 1) % k == a && (ring.closed() || b + 1 < k)) return true;
  return false;
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
                    const RemovalLimits& limits, Patch& out, bool check_topology) {
  const int k = ring.verts;
  if (k < 3) return RejectFold;
  Vec3& u = out.u;
  Vec3& w = out.w;
  plane_basis(n, u, w);
  const Vec3 c = eval.position(v);
  auto& q = out.q; // the plan keeps them for patch_error
  auto& p = out.p;
  for (int i = 0; i < k; ++i) {
    q[i] = eval.position(ring.v[i]);
    Vec3 d = q[i] - c;
    p[i] = {dot(d, u), dot(d, w)};
  }
  const Vec2 o{0, 0};

  // The old fan must project without folds: the ring is then a star-shaped simple polygon
  // around the vertex and any triangulation of it covers the same region.
  for (int i = 0; i < ring.faces; ++i)
    if (!(orient2d(o, p[i], p[(i + 1) % k]) > 0)) return RejectFold;
  if (!ring.closed()) {
    // Open fan: cutting the vertex off must leave a simple polygon, so the vertex must be a
    // convex corner and the chain must lie beyond the new boundary edge.
    if (!(orient2d(p[k - 1], o, p[0]) >= 0)) return RejectFold; // straight is fine
    for (int j = 1; j + 1 < k; ++j)
      if (!(orient2d(p[k - 1], p[0], p[j]) > 0)) return RejectFold;
  }

  if (ring.closed() && is_convex(p.data(), k)) {
    triangulate_fan(p.data(), q.data(), n, k, out);
  } else if (!triangulate_ears(p.data(), q.data(), n, k, out)) {
    return RejectFold;
  }

  out.normal = n;
  // Topology first (it cannot change with the projection), then shape.
  for (int t = 0; t < out.count && check_topology; ++t) {
    const auto& tri = out.tri[t];
    if (topo.has_triangle(ring.v[tri[0]], ring.v[tri[1]], ring.v[tri[2]], tris))
      return RejectTriangle;
    for (int e = 0; e < 3; ++e) {
      int a = tri[e], b = tri[(e + 1) % 3];
      if (!is_ring_edge(ring, a, b) && topo.has_edge(ring.v[a], ring.v[b], tris)) return RejectEdge;
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

} // namespace vrs
