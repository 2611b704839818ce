#include "fold_over.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/geometry.h"
#include "evaluate/local_error.h"

namespace vrs_test {

namespace {

using vrs::Vec3;

Vec3 at(const vrs::Mesh& m, uint32_t v) {
  return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
}

// Input faces bucketed by their boxes on a uniform grid: "every face within R of x".
class FaceGrid {
 public:
  explicit FaceGrid(const vrs::Mesh& m) : m_(m) {
    lo_ = {INFINITY, INFINITY, INFINITY};
    Vec3 hi{-INFINITY, -INFINITY, -INFINITY};
    for (size_t f = 0; f < m.face_count(); ++f)
      if (usable(f))
        for (int c = 0; c < 3; ++c) {
          Vec3 p = at(m, m.triangles[3 * f + c]);
          lo_ = {std::min(lo_.x, p.x), std::min(lo_.y, p.y), std::min(lo_.z, p.z)};
          hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
        }
    const double extent = std::max({hi.x - lo_.x, hi.y - lo_.y, hi.z - lo_.z, 1e-30});
    n_ = std::clamp(int(std::cbrt(double(m.face_count()))), 1, 64);
    cell_ = extent / n_ * (1 + 1e-9);
    cells_.assign(size_t(n_) * n_ * n_, {});
    for (size_t f = 0; f < m.face_count(); ++f) {
      if (!usable(f)) continue;
      int b[3][2];
      box_cells(f, b);
      for (int i = b[0][0]; i <= b[0][1]; ++i)
        for (int j = b[1][0]; j <= b[1][1]; ++j)
          for (int k = b[2][0]; k <= b[2][1]; ++k)
            cells_[index(i, j, k)].push_back(uint32_t(f));
    }
    stamp_.assign(m.face_count(), 0);
  }

  // Faces whose box meets the cube of half side r around x (a superset of those within r).
  template <class Visit> void near(Vec3 x, double r, Visit visit) {
    ++round_;
    int lo[3] = {cell_of(x.x - r, lo_.x), cell_of(x.y - r, lo_.y), cell_of(x.z - r, lo_.z)};
    int hi[3] = {cell_of(x.x + r, lo_.x), cell_of(x.y + r, lo_.y), cell_of(x.z + r, lo_.z)};
    for (int i = lo[0]; i <= hi[0]; ++i)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int k = lo[2]; k <= hi[2]; ++k)
          for (uint32_t f : cells_[index(i, j, k)])
            if (stamp_[f] != round_) {
              stamp_[f] = round_;
              visit(f);
            }
  }
  double cell() const { return cell_; }

 private:
  bool usable(size_t f) const {
    Vec3 a = at(m_, m_.triangles[3 * f]), b = at(m_, m_.triangles[3 * f + 1]),
         c = at(m_, m_.triangles[3 * f + 2]);
    return vrs::is_finite(a) && vrs::is_finite(b) && vrs::is_finite(c) &&
           vrs::length(vrs::cross(b - a, c - a)) > 0;
  }
  int cell_of(double v, double lo) const {
    return std::clamp(int(std::floor((v - lo) / cell_)), 0, n_ - 1);
  }
  size_t index(int i, int j, int k) const { return (size_t(i) * n_ + j) * n_ + k; }
  void box_cells(size_t f, int b[3][2]) const {
    Vec3 p[3];
    for (int c = 0; c < 3; ++c)
      p[c] = at(m_, m_.triangles[3 * f + c]);
    b[0][0] = cell_of(std::min({p[0].x, p[1].x, p[2].x}), lo_.x);
    b[0][1] = cell_of(std::max({p[0].x, p[1].x, p[2].x}), lo_.x);
    b[1][0] = cell_of(std::min({p[0].y, p[1].y, p[2].y}), lo_.y);
    b[1][1] = cell_of(std::max({p[0].y, p[1].y, p[2].y}), lo_.y);
    b[2][0] = cell_of(std::min({p[0].z, p[1].z, p[2].z}), lo_.z);
    b[2][1] = cell_of(std::max({p[0].z, p[1].z, p[2].z}), lo_.z);
  }

  const vrs::Mesh& m_;
  Vec3 lo_;
  int n_ = 1;
  double cell_ = 1;
  std::vector<std::vector<uint32_t>> cells_;
  std::vector<uint32_t> stamp_;
  uint32_t round_ = 0;
};

double distance_to_face(const vrs::Mesh& m, uint32_t f, Vec3 x) {
  return vrs::point_triangle_distance(x, at(m, m.triangles[3 * f]), at(m, m.triangles[3 * f + 1]),
                                      at(m, m.triangles[3 * f + 2]));
}

Vec3 face_normal(const vrs::Mesh& m, size_t f) {
  Vec3 a = at(m, m.triangles[3 * f]);
  return vrs::normalized(
      vrs::cross(at(m, m.triangles[3 * f + 1]) - a, at(m, m.triangles[3 * f + 2]) - a));
}

// The distance from x to the nearest input face (+inf when there is none): the search grows
// until a face within the searched radius is seen.
double nearest_distance(FaceGrid& grid, const vrs::Mesh& in, Vec3 x) {
  double nearest = INFINITY;
  for (double radius = grid.cell(); !(nearest <= radius); radius *= 2) {
    grid.near(x, radius,
              [&](uint32_t g) { nearest = std::min(nearest, distance_to_face(in, g, x)); });
    if (radius > 1e30) break;
  }
  return nearest;
}

} // namespace

size_t count_fold_overs(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r) {
  if (in.face_count() == 0) return 0;
  FaceGrid grid(in);
  auto distance = [&](uint32_t f, Vec3 x) { return distance_to_face(in, f, x); };
  auto normal = face_normal;
  size_t folds = 0;
  for (size_t f = 0; f < out.face_count(); ++f) {
    if (r.face_source[f] != vrs::kRemoved) continue;
    Vec3 a = at(out, out.triangles[3 * f]), b = at(out, out.triangles[3 * f + 1]),
         c = at(out, out.triangles[3 * f + 2]);
    const Vec3 n = normal(out, f), x = (a + b + c) * (1.0 / 3);
    if (!vrs::is_finite(x) || vrs::length(n) == 0) continue;
    const double nearest = nearest_distance(grid, in, x);
    if (!std::isfinite(nearest)) continue;
    const double edge = std::max({vrs::length(b - a), vrs::length(c - b), vrs::length(a - c)});
    const double reach = nearest + 0.5 * edge + 1e-9 * edge;
    bool agrees = false, opposes = false;
    grid.near(x, reach, [&](uint32_t g) {
      if (agrees || distance(g, x) > reach) return;
      double d = vrs::dot(n, normal(in, g));
      agrees = agrees || d > 0;
      opposes = opposes || d < 0;
    });
    folds += opposes && !agrees;
  }
  return folds;
}

size_t count_faces_against_nearest_input(const vrs::Mesh& in, const vrs::Mesh& out) {
  if (in.face_count() == 0) return 0;
  FaceGrid grid(in);
  auto distance = [&](uint32_t f, Vec3 x) { return distance_to_face(in, f, x); };
  auto normal = face_normal;
  size_t folds = 0;
  for (size_t f = 0; f < out.face_count(); ++f) {
    Vec3 a = at(out, out.triangles[3 * f]), b = at(out, out.triangles[3 * f + 1]),
         c = at(out, out.triangles[3 * f + 2]);
    const Vec3 n = normal(out, f), x = (a + b + c) * (1.0 / 3);
    if (!vrs::is_finite(x) || vrs::length(n) == 0) continue;
    const double nearest = nearest_distance(grid, in, x);
    if (!std::isfinite(nearest)) continue;
    const double reach = nearest * (1 + 1e-6) + 1e-12;
    bool agrees = false;
    grid.near(x, reach, [&](uint32_t g) {
      agrees = agrees || (distance(g, x) <= reach && vrs::dot(n, normal(in, g)) > 0);
    });
    folds += !agrees;
  }
  return folds;
}

} // namespace vrs_test
