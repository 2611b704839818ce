#include "fill/candidates.h"

#include <algorithm>

namespace vrs {

namespace {

// The paper's filling: the projected ring is a simple polygon; convex ones get the best fan,
// others ear clipping.
bool fill_projection(const Ring& ring, OpenRing open, Patch& out) {
  const int k = ring.verts;
  const auto& p = out.p;
  const Vec2 o{0, 0};
  // The old fan must project without folds: the ring is then a star-shaped simple polygon
  // around the vertex and any triangulation of it covers the same region.
  for (int i = 0; i < ring.faces; ++i)
    if (!(orient2d(o, p[i], p[wrap(i + 1, k)]) > 0)) return false;
  if (!ring.closed()) {
    // Open fan: cutting the vertex off must leave a simple polygon. At a convex corner the
    // chain must lie beyond the chord; at a reflex one (seams only) the chord lies in the
    // other side's wedge and cannot meet the chain, which is star-shaped around the vertex.
    const bool convex = orient2d(p[k - 1], o, p[0]) >= 0; // straight is fine
    if (!convex && open == OpenRing::Border) return false;
    for (int j = 1; j + 1 < k && convex; ++j)
      if (!(orient2d(p[k - 1], p[0], p[j]) > 0)) return false;
  }
  if (ring.closed() && is_convex(p.data(), k)) {
    triangulate_fan(p.data(), out.q.data(), out.normal, k, out);
    return true;
  }
  return triangulate_ears(p.data(), out.q.data(), out.normal, k, out);
}

// Fan from ring vertex `apex` over the polygon (ring, closed by the chord when open): one
// triangle per polygon edge not at the apex.
void fill_fan(const Ring& ring, int apex, Patch& out) {
  const int k = ring.verts;
  out.count = 0;
  for (int i = 1; i + 1 < k; ++i)
    out.tri[out.count++] = {uint8_t(apex), uint8_t(wrap(apex + i, k)),
                            uint8_t(wrap(apex + i + 1, k))};
}

} // namespace

int fan_candidate(const Ring& ring, const Patch& patch) {
  const int k = ring.verts;
  if (k < 3 || patch.count != k - 2) return -1;
  const int apex = patch.tri[0][0];
  for (int i = 1; i + 1 < k; ++i) {
    const auto& t = patch.tri[i - 1];
    if (t[0] != apex || t[1] != wrap(apex + i, k) || t[2] != wrap(apex + i + 1, k)) return -1;
  }
  return k == 3 ? (apex == 0 ? 1 : -1) : 1 + apex; // a three-vertex ring: one fan, apex 0
}

bool fill_triangles(const Ring& ring, OpenRing open, int c, Patch& out) {
  if (ring.verts == 2) { // one triangle cut off: its edge between the two neighbours stays
    out.count = 0;
    return !ring.closed();
  }
  if (c == 0) return fill_projection(ring, open, out);
  fill_fan(ring, c - 1, out);
  return true;
}

bool fill_candidate(const Ring& ring, OpenRing open, int c, Patch& out) {
  if (!fill_triangles(ring, open, c, out)) return false;
  set_corner_faces(ring, out);
  return true;
}

void set_corner_faces(const Ring& ring, Patch& out) {
  // Per-corner data: ring face i holds ring vertices i and i + 1, so the face numbered as the
  // corner's vertex (the last face for an open ring's last vertex) holds it.
  for (int t = 0; t < out.count; ++t)
    for (int c3 = 0; c3 < 3; ++c3)
      out.from[t][c3] = static_cast<uint8_t>(std::min(int(out.tri[t][c3]), ring.faces - 1));
}

} // namespace vrs
