#include "fill/triangulation.h"

namespace vrs {

int triangle_under(const Patch& patch, Vec2 s) {
  for (int t = 0; t < patch.count; ++t) {
    const auto& tri = patch.tri[t];
    const Vec2 a = patch.p[tri[0]], b = patch.p[tri[1]], e = patch.p[tri[2]];
    if (orient2d(a, b, s) >= 0 && orient2d(b, e, s) >= 0 && orient2d(e, a, s) >= 0) return t;
  }
  return -1;
}

void set_replaced_faces(Vec3 c, const Ring& ring, Patch& patch) {
  for (int i = 0; i < ring.faces; ++i) {
    const Vec3 x = cross(patch.q[i] - c, patch.q[wrap(i + 1, ring.verts)] - c);
    patch.face_area[i] = 0.5 * length(x);
    patch.face_n[i] = normalized(x);
  }
}

bool is_convex(const Vec2* p, int k) {
  for (int i = 0; i < k; ++i)
    if (!(orient2d(p[i], p[wrap(i + 1, k)], p[wrap(i + 2, k)]) > 0)) return false;
  return true;
}

void triangulate_fan(const Vec2*, const Vec3* q, Vec3 n, int k, Patch& out) {
  // triangle_score's terms shared: the ring's edges once, an apex's spokes as its triangles
  // come (each spoke is in two of them). The same arithmetic, a third fewer instructions.
  std::array<double, kMaxRing + 1> edge2;
  for (int j = 0; j < k; ++j) {
    const Vec3 e = q[wrap(j + 1, k)] - q[j];
    edge2[j] = dot(e, e);
  }
  int best = 0;
  double best_worst = -1;
  for (int a = 0; a < k; ++a) {
    double worst = 1;
    Vec3 spoke = q[wrap(a + 1, k)] - q[a];
    double spoke2 = dot(spoke, spoke);
    // A fan no better than the best so far cannot win: its worst triangle only falls.
    for (int i = 1; i + 1 < k && worst > best_worst; ++i) {
      const int j = wrap(a + i, k);
      const Vec3 next = q[wrap(j + 1, k)] - q[a];
      const double next2 = dot(next, next); // |a - c|² of triangle_score, the same product
      worst = std::min(worst, score_of(dot(cross(spoke, next), n), spoke2 + edge2[j] + next2));
      spoke = next, spoke2 = next2;
    }
    if (worst > best_worst) {
      best_worst = worst;
      best = a;
    }
  }
  out.count = 0;
  for (int i = 1; i + 1 < k; ++i)
    out.tri[out.count++] = {uint8_t(best), uint8_t(wrap(best + i, k)),
                            uint8_t(wrap(best + i + 1, k))};
}

namespace {

// Is x inside or on the triangle (a, b, c), counter-clockwise?
bool in_triangle(Vec2 a, Vec2 b, Vec2 c, Vec2 x) {
  return orient2d(a, b, x) >= 0 && orient2d(b, c, x) >= 0 && orient2d(c, a, x) >= 0;
}

} // namespace

bool triangulate_ears(const Vec2* p, const Vec3* q, Vec3 normal, int k, Patch& out) {
  std::array<uint8_t, kMaxRing + 1> poly;
  int n = k;
  for (int i = 0; i < k; ++i)
    poly[i] = uint8_t(i);
  out.count = 0;
  while (n > 3) {
    int best = -1;
    double best_quality = -1;
    for (int i = 0; i < n; ++i) {
      uint8_t a = poly[(i + n - 1) % n], b = poly[i], c = poly[(i + 1) % n];
      if (!(orient2d(p[a], p[b], p[c]) > 0)) continue; // reflex or flat corner
      bool empty = true;
      for (int j = 0; j < n && empty; ++j) {
        uint8_t x = poly[j];
        if (x != a && x != b && x != c && in_triangle(p[a], p[b], p[c], p[x])) empty = false;
      }
      if (!empty) continue;
      double quality = triangle_score(q[a], q[b], q[c], normal);
      if (quality > best_quality) {
        best_quality = quality;
        best = i;
      }
    }
    if (best < 0) return false;
    out.tri[out.count++] = {poly[(best + n - 1) % n], poly[best], poly[(best + 1) % n]};
    for (int j = best; j + 1 < n; ++j)
      poly[j] = poly[j + 1];
    --n;
  }
  if (!(orient2d(p[poly[0]], p[poly[1]], p[poly[2]]) > 0)) return false;
  out.tri[out.count++] = {poly[0], poly[1], poly[2]};
  return true;
}

} // namespace vrs
