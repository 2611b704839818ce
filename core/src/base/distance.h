// Exact distances from a point to a triangle and to a segment: what pricing, the input
// surface, the error bound and the slide all measure with.
#pragma once

#include <algorithm>
#include <cmath>

#include "base/geometry.h"

namespace vrs {

constexpr double kFarCorner2 = 1e12; // squared: a corner 1e6 times farther

// Squared distance from p to the triangle (a0, b0, c0), exact (the closest point on it).
inline double point_triangle_distance2(const Vec3& p, const Vec3& a0, const Vec3& b0,
                                       const Vec3& c0) {
  auto len2 = [](Vec3 d) { return dot(d, d); };
  // From a corner a million times farther than another the region tests cancel (a face with
  // a corner at 1e21 put a point 33 from it at 105 or 1.3e5, the fuzzer's spike): measured
  // from the nearest corner then. Only then: elsewhere the same arithmetic, the same ties.
  // (The corners by reference: by value, 24 bytes each, every call copied them.)
  const Vec3 *ra = &a0, *rb = &b0, *rc = &c0;
  const double pa = len2(p - a0), pb = len2(p - b0), pc = len2(p - c0);
  if (pa > kFarCorner2 * std::min(pb, pc)) {
    if (pb <= pc)
      ra = &b0, rb = &c0, rc = &a0;
    else
      ra = &c0, rb = &a0, rc = &b0;
  }
  const Vec3 &a = *ra, &b = *rb, &c = *rc;
  // Voronoi regions of the triangle's vertices, edges and face, in that order.
  Vec3 ab = b - a, ac = c - a, ap = p - a;
  double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return len2(ap);
  Vec3 bp = p - b;
  double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return len2(bp);
  double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return len2(p - (a + ab * (d1 / (d1 - d3))));
  Vec3 cp = p - c;
  double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return len2(cp);
  double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return len2(p - (a + ac * (d2 / (d2 - d6))));
  double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return len2(p - (b + (c - b) * w));
  }
  double denom = va + vb + vc;
  if (!(std::fabs(denom) > 0)) // no area: the nearest of its edges
    return std::min({len2(ap), len2(bp), len2(cp)});
  double v = vb / denom, w = vc / denom;
  return len2(p - (a + ab * v + ac * w));
}

inline double point_triangle_distance(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  return std::sqrt(point_triangle_distance2(p, a, b, c));
}

// Distance from p to the segment (a, b).
inline double distance_to_segment(Vec3 p, Vec3 a, Vec3 b) {
  Vec3 ab = b - a;
  double len2 = dot(ab, ab), t = len2 > 0 ? dot(p - a, ab) / len2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  return length(p - (a + ab * t));
}

} // namespace vrs
