#include "evaluate/error_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/distance.h"

namespace vrs {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A convex polygon of the plane: a triangle clipped by a triangle has at most 6 corners, and a
// corner on a clipping line may repeat; 32 is room enough.
struct Polygon {
  int n = 0;
  std::array<Vec2, 32> p;
};

// Keeps the part of `in` on the left of (a, b), Sutherland-Hodgman.
void clip(const Polygon& in, Vec2 a, Vec2 b, Polygon& out) {
  out.n = 0;
  for (int i = 0; i < in.n && out.n + 2 <= int(out.p.size()); ++i) {
    const Vec2 x = in.p[i], y = in.p[(i + 1) % in.n];
    const double sx = orient2d(a, b, x), sy = orient2d(a, b, y);
    if (sx >= 0) out.p[out.n++] = x;
    if ((sx >= 0) != (sy >= 0)) {
      const double t = sx / (sx - sy);
      out.p[out.n++] = {x.x + (y.x - x.x) * t, x.y + (y.y - x.y) * t};
    }
  }
}

// The part of triangle (a, b, c) inside the counter-clockwise triangle (d, e, f).
void intersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d, Vec2 e, Vec2 f, Polygon& out) {
  Polygon x, y;
  x.n = 3, x.p[0] = a, x.p[1] = b, x.p[2] = c;
  clip(x, d, e, y);
  clip(y, e, f, x);
  clip(x, f, d, out);
}

double area2(const Polygon& poly) {
  double s = 0;
  for (int i = 1; i + 1 < poly.n; ++i)
    s += orient2d(poly.p[0], poly.p[i], poly.p[i + 1]);
  return s;
}

// The point of triangle (a, b, c) (3D: qa, qb, qc) that projects to x.
Vec3 lift(Vec2 x, Vec2 a, Vec2 b, Vec2 c, Vec3 qa, Vec3 qb, Vec3 qc) {
  const double area = orient2d(a, b, c);
  const double la = orient2d(x, b, c) / area, lb = orient2d(a, x, c) / area;
  return qa * la + qb * lb + qc * (1.0 - la - lb);
}

// Rounded up, so that the stored bound stays a bound.
float round_up(double x) {
  float f = static_cast<float>(x);
  if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

// Both the old fan and the patch tile the same region of the plan's plane, once each.
bool projects_one_to_one(const Ring& ring, const Patch& patch) {
  const int k = ring.verts;
  const auto& p = patch.p;
  const Vec2 o{0, 0};
  double turn = 0; // the fan's angle around v
  for (int i = 0; i < ring.faces; ++i) {
    const Vec2 a = p[i], b = p[(i + 1) % k];
    if (!(orient2d(o, a, b) > 0)) return false;
    turn += std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
  }
  if (ring.closed()) {
    if (!(turn < 3 * kPi)) return false; // the ring winds twice around v
  } else {
    // A convex border corner whose chain lies beyond the chord: the patch's region is the
    // fan's minus the corner triangle (v, first, last).
    if (!(turn <= kPi) || orient2d(p[k - 1], o, p[0]) < 0) return false;
    for (int j = 1; j + 1 < k; ++j)
      if (!(orient2d(p[k - 1], p[0], p[j]) > 0)) return false;
  }
  for (int t = 0; t < patch.count; ++t)
    if (!(orient2d(p[patch.tri[t][0]], p[patch.tri[t][1]], p[patch.tri[t][2]]) > 0)) return false;
  return true;
}

} // namespace

bool bound_patch(const Ring& ring, Patch& patch, Vec3 c, const float* face_bound) {
  if (patch.count == 0 || !projects_one_to_one(ring, patch)) return false;
  const int k = ring.verts;
  const auto& p = patch.p;
  const auto& q = patch.q;
  const Vec2 o{0, 0};
  Polygon cell;
  for (int t = 0; t < patch.count; ++t) {
    const auto& tri = patch.tri[t];
    const Vec2 a = p[tri[0]], b = p[tri[1]], d = p[tri[2]];
    const double own = orient2d(a, b, d);
    double e = 0;
    for (int f = 0; f < ring.faces; ++f) {
      const int g = (f + 1) % k;
      intersect(a, b, d, o, p[f], p[g], cell);
      // Cells without area add nothing: their points lie in cells that have some.
      if (cell.n < 3 || !(area2(cell) > 1e-12 * own)) continue;
      double gap = 0;
      for (int i = 0; i < cell.n; ++i) {
        const Vec2 x = cell.p[i];
        gap = std::max(gap, length(lift(x, a, b, d, q[tri[0]], q[tri[1]], q[tri[2]]) -
                                   lift(x, o, p[f], p[g], c, q[f], q[g])));
      }
      e = std::max(e, gap + double(face_bound[ring.f[f]]));
    }
    patch.bound[t] = round_up(e);
  }
  if (!ring.closed() && orient2d(o, p[0], p[k - 1]) > 0) {
    // The corner cut off: its input lies near the new border edge (last, first).
    int edge = -1;
    for (int t = 0; t < patch.count && edge < 0; ++t)
      for (int i = 0; i < 3; ++i)
        if ((patch.tri[t][i] == k - 1 && patch.tri[t][(i + 1) % 3] == 0)) edge = t;
    if (edge < 0) return false;
    double e = patch.bound[edge];
    for (int f = 0; f < ring.faces; ++f) {
      const int g = f + 1;
      intersect(o, p[0], p[k - 1], o, p[f], p[g], cell);
      if (cell.n < 3) continue;
      double gap = 0;
      for (int i = 0; i < cell.n; ++i)
        gap = std::max(gap, distance_to_segment(lift(cell.p[i], o, p[f], p[g], c, q[f], q[g]),
                                                q[k - 1], q[0]));
      e = std::max(e, gap + double(face_bound[ring.f[f]]));
    }
    patch.bound[edge] = round_up(e);
  }
  return true;
}

} // namespace vrs
