#include "evaluate/local_error.h"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>

#include "base/workers.h"

namespace vrs {

OldFan::OldFan(uint32_t v, const Ring& ring, const Patch& patch, const Evaluator& eval)
    : ring_(ring), patch_(patch), c_(eval.position(v)), n_(patch.face_n) {
  for (int i = 0; i < ring.faces; ++i)
    area_ += patch.face_area[i];
}

double OldFan::to_face2(Vec3 x, int i, double best) const {
  const double h = dot(x - c_, n_[i]);
  if (h * h >= best) return best;
  return std::min(best,
                  point_triangle_distance2(x, c_, patch_.q[i], patch_.q[wrap(i + 1, ring_.verts)]));
}

double OldFan::distance2(Vec3 x) const {
  // The old fan projects without folds along the patch's normal, so a point of the new patch
  // lies over one old triangle: measure to it and its two neighbours (to all of them if
  // rounding says it lies over none).
  const int k = ring_.verts;
  const auto& p = patch_.p;
  const Vec2 o{0, 0};
  const Vec2 s{dot(x - c_, patch_.u), dot(x - c_, patch_.w)};
  double d = std::numeric_limits<double>::infinity();
  for (int i = 0; i < ring_.faces; ++i) {
    const int j = wrap(i + 1, k);
    if (!(orient2d(o, p[i], s) >= 0 && orient2d(o, s, p[j]) >= 0 && orient2d(p[i], p[j], s) >= 0))
      continue;
    d = point_triangle_distance2(x, c_, patch_.q[i], patch_.q[j]);
    if (i > 0 || ring_.closed()) d = to_face2(x, wrap(i + k - 1, k), d);
    if (j < ring_.faces) d = to_face2(x, j, d);
    return d;
  }
  for (int i = 0; i < ring_.faces; ++i)
    d = to_face2(x, i, d);
  return d;
}

bool OldFan::opposes_near(Vec3 x, Vec3 n, double slack) const {
  const int k = ring_.verts;
  std::array<double, kMaxRing> d;
  double nearest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < ring_.faces; ++i) {
    d[i] = std::sqrt(point_triangle_distance2(x, c_, patch_.q[i], patch_.q[wrap(i + 1, k)]));
    nearest = std::min(nearest, d[i]);
  }
  for (int i = 0; i < ring_.faces; ++i)
    if (d[i] <= nearest + slack && dot(n, n_[i]) > 0) return false;
  return true;
}

namespace {

// Whether (i, j) (ring positions) is a new edge of a patch: not a ring edge (an open ring's
// closing edge is new too).
bool is_new_edge(const Ring& ring, int i, int j) {
  const int k = ring.verts;
  return !(i + 1 == j || j + 1 == i ||
           (ring.closed() && ((i == k - 1 && j == 0) || (j == k - 1 && i == 0))));
}

} // namespace

double triangle_error2(const OldFan& fan, const Ring& ring, const Patch& patch, int a, int b,
                       int c) {
  const auto& q = patch.q;
  double worst = fan.distance2((q[a] + q[b] + q[c]) * (1.0 / 3));
  const int corner[3] = {a, b, c};
  for (int e = 0; e < 3; ++e) {
    const int i = corner[e], j = corner[(e + 1) % 3];
    if (is_new_edge(ring, i, j)) worst = std::max(worst, fan.distance2((q[i] + q[j]) * 0.5));
  }
  return worst;
}

namespace {

// Squared distance from x to the patch's nearest new triangle: triangle `first` (the likeliest),
// then the others only where their plane is nearer than the best so far.
double to_patch2(const Patch& patch, Vec3 x, int first = 0) {
  const auto& q = patch.q;
  double best = std::numeric_limits<double>::infinity();
  for (int n = 0; n < patch.count; ++n) {
    const auto& tri = patch.tri[(first + n) % patch.count];
    const Vec3 a = q[tri[0]], b = q[tri[1]], d = q[tri[2]];
    if (n > 0) { // plane distance^2 = dot(x - a, m)^2 / |m|^2
      const Vec3 m = cross(b - a, d - a);
      const double h = dot(x - a, m), mm = dot(m, m);
      if (mm > 0 && h * h >= best * mm) continue;
    }
    best = std::min(best, point_triangle_distance2(x, a, b, d));
  }
  return best;
}

} // namespace

double patch_error(uint32_t v, const Ring& ring, const Patch& patch, const Evaluator& eval,
                   double reference_area) {
  const int k = ring.verts;
  const Vec3 c = eval.position(v);
  const auto& q = patch.q; // as planned: positions, and their projections `p` on (u, w)
  const auto& p = patch.p;
  const Vec2 o{0, 0};
  // Squared distances throughout (one square root at the end).
  const OldFan fan(v, ring, patch, eval);
  const double area = fan.area();

  double worst = 0;
  std::array<double, kMaxRing> centroid2; // the new centroids to the old fan, squared
  for (int t = 0; t < patch.count; ++t) {
    const auto& tri = patch.tri[t];
    Vec3 a = q[tri[0]], b = q[tri[1]], d = q[tri[2]];
    centroid2[t] = fan.distance2((a + b + d) * (1.0 / 3));
    worst = std::max(worst, centroid2[t]);
    for (int e = 0; e < 3; ++e) {
      int i = tri[e], j = tri[(e + 1) % 3];
      // Ring edges are kept as they are; each diagonal is shared by two new triangles:
      // measure it once.
      if (is_new_edge(ring, i, j) && (i < j || (i == k - 1 && j == 0)))
        worst = std::max(worst, fan.distance2((q[i] + q[j]) * 0.5));
    }
  }
  // The removed vertex to the new patch, from the triangle it projects into (usually the
  // nearest).
  int first = 0;
  for (int t = 0; t < patch.count; ++t) {
    const auto& tri = patch.tri[t];
    if (orient2d(p[tri[0]], p[tri[1]], o) >= 0 && orient2d(p[tri[1]], p[tri[2]], o) >= 0 &&
        orient2d(p[tri[2]], p[tri[0]], o) >= 0) {
      first = t;
      break;
    }
  }
  double to_new = patch.count ? to_patch2(patch, c, first) : 0.0;
  // A triangle cut off (no patch): the surface now ends at the edge between the two neighbours.
  if (patch.count == 0 && k == 2) {
    const double d = distance_to_segment(c, q[0], q[1]);
    to_new = d * d;
  }
  const double local = std::sqrt(std::max(worst, to_new)) * std::sqrt(area / reference_area);
  // Off creases the local price alone: priced so everywhere, a smooth mesh took more time for
  // more error, and wherever a corner was turned from its triangle (coarse organic meshes too)
  // small outputs lost accuracy and their target.
  if (!(patch.unsure_corners & kCornerOnCrease) || patch.count == 0) return local;
  const double moved = moved_surface(fan, ring, patch, c, centroid2.data());
  return std::max(local, std::sqrt(local * moved / reference_area));
}

double moved_surface(const OldFan& fan, const Ring& ring, const Patch& patch, Vec3 c,
                     const double* centroid2) {
  const auto& q = patch.q;
  auto to_patch = [&](Vec3 x) { return std::sqrt(to_patch2(patch, x)); };
  double moved = 0;
  for (int i = 0; i < ring.faces; ++i) { // the old face's centroid and a point nearer c
    const Vec3 a = q[i], b = q[wrap(i + 1, ring.verts)];
    const double area = 0.5 * length(cross(a - c, b - c));
    moved += area * 0.5 * (to_patch((a + b + c) * (1.0 / 3)) + to_patch((a + b + c * 2.0) * 0.25));
  }
  for (int t = 0; t < patch.count; ++t) {
    const auto& tri = patch.tri[t];
    const Vec3 a = q[tri[0]], b = q[tri[1]], d = q[tri[2]];
    const double d2 = centroid2 ? centroid2[t] : fan.distance2((a + b + d) * (1.0 / 3));
    moved += 0.5 * length(cross(b - a, d - a)) * std::sqrt(d2);
  }
  return moved;
}

double drop_height(uint32_t v, const Patch& patch, const Evaluator& eval, double cap,
                   bool& complete) {
  const Vec3 c = eval.position(v);
  // Squared: one square root per patch, none per triangle. Past the cap squared (rounded up a
  // little: the square root taken afterwards must not come back under the cap) it stops.
  const double stop = cap * cap * (1 + 1e-12);
  double worst = 0;
  complete = true;
  for (int t = 0; t < patch.count; ++t) {
    Vec3 x = patch.q[patch.tri[t][0]], y = patch.q[patch.tri[t][1]], z = patch.q[patch.tri[t][2]];
    Vec3 n = cross(y - x, z - x);
    double h = dot(c - x, n), nn = dot(n, n);
    if (nn > 0) worst = std::max(worst, h * h / nn);
    if (worst > stop && t + 1 < patch.count) {
      complete = false;
      break;
    }
  }
  return std::sqrt(worst);
}

double drop_height(uint32_t v, const Patch& patch, const Evaluator& eval) {
  bool complete;
  return drop_height(v, patch, eval, std::numeric_limits<double>::infinity(), complete);
}

double mean_triangle_area(const float* pos, const std::vector<uint32_t>& tris, Workers* workers) {
  // Summed in blocks of a fixed size, the blocks' sums in order: one result on any threads.
  constexpr size_t kBlock = 3 * 65536;
  std::vector<std::pair<double, size_t>> part((tris.size() + kBlock - 1) / kBlock);
  for_each_block(workers, tris.size() - tris.size() % 3, kBlock, [&](size_t begin, size_t end) {
    auto at = [&](uint32_t v) { return Vec3{pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]}; };
    auto& [sum, n] = part[begin / kBlock];
    for (size_t i = begin; i < end; i += 3) {
      Vec3 a = at(tris[i]);
      double area = 0.5 * length(cross(at(tris[i + 1]) - a, at(tris[i + 2]) - a));
      if (std::isfinite(area)) sum += area, ++n;
    }
  });
  double sum = 0;
  size_t n = 0;
  for (const auto& p : part)
    sum += p.first, n += p.second;
  return n && sum > 0 ? sum / double(n) : 1.0;
}

} // namespace vrs
