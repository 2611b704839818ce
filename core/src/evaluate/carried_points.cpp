#include "evaluate/carried_points.h"

#include <array>
#include <limits>

#include "base/distance.h"

namespace vrs {

namespace {

// Squared distance from x to the nearest of the patch's triangles, or any value <= `enough`
// as soon as one triangle is that near (the caller only needs to know x is no farther).
double nearest2(Vec3 x, const Patch& patch, double enough, int* which = nullptr) {
  double best = std::numeric_limits<double>::infinity();
  for (int t = 0; t < patch.count; ++t) {
    const auto& tri = patch.tri[t];
    const Vec3 a = patch.q[tri[0]], b = patch.q[tri[1]], c = patch.q[tri[2]];
    const Vec3 m = cross(b - a, c - a);
    const double h = dot(x - a, m), mm = dot(m, m);
    if (mm > 0 && h * h >= best * mm) continue; // its plane is farther than the best so far
    const double d = point_triangle_distance2(x, a, b, c);
    if (d < best) {
      best = d;
      if (which) *which = t;
      if (best <= enough) break;
    }
  }
  return best;
}

} // namespace

bool CarriedPoints::folds_input(uint32_t v, const Ring& ring, const Patch& patch,
                                const Positions& eval, const float* cones) const {
  if (patch.count == 0) return false;
  std::array<Vec3, kMaxRing> n; // the new triangles' unit normals
  // Their spread around the plan's normal N: all within the angle b of it (cos b = least).
  double least = 1;
  for (int t = 0; t < patch.count; ++t) {
    const auto& tri = patch.tri[t];
    n[t] = normalized(cross(patch.q[tri[1]] - patch.q[tri[0]], patch.q[tri[2]] - patch.q[tri[0]]));
    least = std::min(least, dot(n[t], patch.normal));
  }
  const double sin_b = std::sqrt(std::max(0.0, 1 - least * least));
  const Vec3 c = eval.position(v);
  auto folds_at = [&](uint32_t p) {
    const float* cone = cones + 4 * size_t(p);
    const Vec3 axis{cone[0], cone[1], cone[2]};
    // No new triangle can face away when the cone axis is within a of N and a + b stays under
    // 90 degrees plus the cone's own spread: cos(a + b) > -slack. The common case on a smooth
    // part, decided without looking for the triangle the point lies under.
    const double cos_a = dot(axis, patch.normal);
    if (least > 0 && cos_a > 0 &&
        cos_a * least - std::sqrt(std::max(0.0, 1 - cos_a * cos_a)) * sin_b > -cone[3] + 1e-9)
      return false;
    const Vec3 d = eval.position(p) - c;
    const Vec2 s{dot(d, patch.u), dot(d, patch.w)};
    const int t = triangle_under(patch, s);
    return t >= 0 && !(dot(n[t], axis) > -cone[3]); // outside: another removal's business
  };
  if (folds_at(v)) return true;
  for (int i = 0; i < ring.faces; ++i)
    for (uint32_t p = head_[ring.f[i]]; p != kNone; p = next_[p])
      if (folds_at(p)) return true;
  return false;
}

uint32_t CarriedPoints::gather(uint32_t v, const Ring& ring, uint32_t skip) {
  uint32_t chain = v;
  next_[v] = kNone;
  for (int i = 0; i < ring.faces; ++i) {
    uint32_t& h = head_[ring.f[i]];
    for (uint32_t p = h; p != kNone;) {
      const uint32_t after = next_[p];
      if (p != skip) {
        next_[p] = chain;
        chain = p;
      }
      p = after;
    }
    h = kNone;
  }
  return chain;
}

void CarriedPoints::hand_over(uint32_t v, const Ring& ring, const Patch& patch,
                              const Positions& eval) {
  const uint32_t chain = gather(v, ring, kNone);
  if (patch.count == 0) return; // nothing stands for them any more: the triangle went
  const Vec3 c = eval.position(v);
  for (uint32_t p = chain; p != kNone;) {
    const uint32_t after = next_[p];
    // The triangle it lies under along the plan's normal (the patch projects one-to-one
    // there), else, beyond the ring, the nearest.
    const Vec3 d = eval.position(p) - c;
    const Vec2 s{dot(d, patch.u), dot(d, patch.w)};
    int t = triangle_under(patch, s);
    if (t < 0) nearest2(eval.position(p), patch, -1.0, &t);
    uint32_t& h = head_[ring.f[t]];
    next_[p] = h;
    h = p;
    p = after;
  }
}

void CarriedPoints::slide(uint32_t v, uint32_t u, const Ring& ring, const Patch& fan,
                          const Positions& eval) {
  const uint32_t chain = gather(v, ring, u);
  next_[u] = kNone;
  for (uint32_t p = chain; p != kNone;) {
    const uint32_t after = next_[p];
    int t = 0;
    nearest2(eval.position(p), fan, -1.0, &t);
    uint32_t& h = head_[ring.f[t]];
    next_[p] = h;
    h = p;
    p = after;
  }
}

} // namespace vrs
