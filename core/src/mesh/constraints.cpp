#include "mesh/constraints.h"

#include <cmath>

#include "base/geometry.h"

namespace vrs {

void Constraints::add(uint32_t a, uint32_t b) {
  if (a == b || !edges_.insert(a, b)) return;
  if (degree_[a] < 255) ++degree_[a];
  if (degree_[b] < 255) ++degree_[b];
}

size_t Constraints::build(const Options& o, const float* pos, const std::vector<uint32_t>& tris,
                          const Topology& topo, size_t n) {
  const bool given = o.constrained_edges && !o.constrained_edges->empty();
  if (!given && !(o.feature_angle_deg > 0)) return 0;
  degree_.assign(n, 0);
  if (given) {
    const auto& e = *o.constrained_edges;
    for (size_t i = 0; i + 1 < e.size(); i += 2)
      if (topo.edge_faces(e[i], e[i + 1], tris.data()) > 0) add(e[i], e[i + 1]); // exact, once
  }
  if (o.feature_angle_deg > 0) {
    // Each manifold edge once, from the face that holds it as (a, b) with a < b... both faces
    // hold it, one in each direction: compare the face with its neighbour across the edge.
    const double min_cos = std::cos(o.feature_angle_deg * 3.14159265358979323846 / 180);
    auto at = [&](uint32_t v) { return Vec3{pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]}; };
    auto normal = [&](uint32_t f) {
      Vec3 a = at(tris[3 * f]), b = at(tris[3 * f + 1]), c = at(tris[3 * f + 2]);
      return normalized(cross(b - a, c - a));
    };
    for (uint32_t f = 0; 3 * size_t(f) < tris.size(); ++f)
      for (int c = 0; c < 3; ++c) {
        uint32_t a = tris[3 * f + c], b = tris[3 * f + (c + 1) % 3];
        // The other face of the edge, looked at from the lower-numbered face only.
        const uint32_t* fs = topo.faces_of(a);
        for (uint32_t i = 0; i < topo.valence(a); ++i) {
          uint32_t g = fs[i];
          const uint32_t* t = &tris[3 * size_t(g)];
          if (g <= f || (t[0] != b && t[1] != b && t[2] != b)) continue;
          if (dot(normal(f), normal(g)) < min_cos) add(a, b);
        }
      }
  }
  return edges_.size();
}

bool Constraints::seam_of(uint32_t v, const Ring& ring, int& i, int& j) const {
  if (degree(v) != 2 || !ring.closed()) return false;
  int found = 0;
  for (int r = 0; r < ring.verts && found < 2; ++r)
    if (has(v, ring.v[r])) (found++ == 0 ? i : j) = r;
  return found == 2;
}

void Constraints::merge(uint32_t v, uint32_t a, uint32_t b) {
  edges_.erase(v, a);
  edges_.erase(v, b);
  degree_[v] = 0;
  // a and b each lose (v, x) and gain (a, b), unless (a, b) was constrained already.
  if (!edges_.insert(a, b)) {
    if (degree_[a] < 255) --degree_[a];
    if (degree_[b] < 255) --degree_[b];
  }
}

} // namespace vrs
