#include "evaluate/local_input.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "evaluate/input_surface.h"
#include "evaluate/local_error.h"

namespace {

using vrs::Vec3;

// The faces as slide_local() sets them: corners, unit normal, bounding sphere, mean area.
void set_faces(vrs::LocalInput& in, const std::vector<std::array<Vec3, 3>>& faces) {
  in.resize(faces.size());
  in.count = 0;
  in.mean_area = 0;
  for (const auto& f : faces) {
    const Vec3 n = vrs::cross(f[1] - f[0], f[2] - f[0]);
    const int k = in.count++;
    in.a[k] = f[0], in.b[k] = f[1], in.c[k] = f[2], in.n[k] = vrs::normalized(n);
    const Vec3 m = (f[0] + f[1] + f[2]) * (1.0 / 3);
    in.cx[k] = m.x, in.cy[k] = m.y, in.cz[k] = m.z;
    double r2 = 0;
    for (const Vec3& p : f)
      r2 = std::max(r2, vrs::dot(p - m, p - m));
    in.radius[k] = std::sqrt(r2) * (1 + 1e-12);
    in.mean_area += 0.5 * vrs::length(n);
  }
  in.mean_area /= in.count;
}

// An n x n grid of squares of side 1 from the origin, two triangles each, facing +z; heights
// from `height` (0: flat).
template <class Height> std::vector<std::array<Vec3, 3>> grid(int n, Height height) {
  std::vector<std::array<Vec3, 3>> faces;
  auto at = [&](int i, int j) { return Vec3{double(i), double(j), height(i, j)}; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return faces;
}

// A fan of k triangles around (cx, cy, z), its ring a regular polygon of radius r at height z;
// `up`: counter-clockwise seen from +z.
vrs::Patch fan(double cx, double cy, double z, double r, int k, bool up, double apex_dz = 0) {
  vrs::Patch p;
  for (int i = 0; i < k; ++i) {
    const double t = 2 * M_PI * i / k;
    p.q[i] = {cx + r * std::cos(t), cy + r * std::sin(t), z};
    p.tri[i] = up ? std::array<uint8_t, 3>{uint8_t(i), uint8_t((i + 1) % k), uint8_t(k)}
                  : std::array<uint8_t, 3>{uint8_t((i + 1) % k), uint8_t(i), uint8_t(k)};
  }
  p.q[k] = {cx, cy, z + apex_dz};
  p.count = k;
  return p;
}

double area(const vrs::Patch& p) {
  double a = 0;
  for (int t = 0; t < p.count; ++t)
    a += 0.5 * vrs::length(vrs::cross(p.q[p.tri[t][1]] - p.q[p.tri[t][0]],
                                      p.q[p.tri[t][2]] - p.q[p.tri[t][0]]));
  return a;
}

// What measure_against computes, by reading every face for every point: the reference its
// shortcuts (the last nearest face's reach, the nearest centre first) must reproduce.
double brute_measure(const vrs::Patch& patch, const vrs::LocalInput& in, bool& folds,
                     double& farthest) {
  double out = 0;
  folds = false;
  const int L = 2;
  for (int t = 0; t < patch.count; ++t) {
    const Vec3 a = patch.q[patch.tri[t][0]], b = patch.q[patch.tri[t][1]],
               c = patch.q[patch.tri[t][2]];
    const Vec3 nt = vrs::cross(b - a, c - a);
    const double w = 0.5 * vrs::length(nt);
    vrs::each_grid_point(a, b, c, L, [&](Vec3 x) {
      std::vector<double> d2(size_t(in.count));
      double best = std::numeric_limits<double>::infinity();
      for (int f = 0; f < in.count; ++f)
        best = std::min(best, d2[f] = vrs::point_triangle_distance2(x, in.a[f], in.b[f], in.c[f]));
      out += w / (L * L) * std::sqrt(best);
      farthest = std::max(farthest, best);
      // Every face as near: one within 60 degrees, or their normals summed within 90.
      const double tie = vrs::InputSurface::tie_reach2(best, x);
      bool near60 = false;
      Vec3 sum{0, 0, 0};
      for (int f = 0; f < in.count; ++f)
        if (d2[f] <= tie) {
          near60 = near60 || vrs::dot(in.n[f], nt) > vrs::InputSurface::kAgreeAlone * 2 * w;
          sum = sum + in.n[f];
        }
      folds = folds || !(near60 || vrs::dot(sum, nt) > 0);
      return false;
    });
  }
  return out;
}

TEST(LocalInput, AFanAboveAFlatInputMeasuresItsHeightTimesItsArea) {
  vrs::LocalInput in;
  set_faces(in, grid(8, [](int, int) { return 0.0; }));
  bool folds = true;
  double farthest = 0;
  const vrs::Patch above = fan(4, 4, 0.25, 2, 6, true);
  EXPECT_NEAR(vrs::measure_against(above, in, folds, HUGE_VAL, false, &farthest),
              0.25 * area(above), 1e-9);
  EXPECT_FALSE(folds);
  EXPECT_NEAR(farthest, 0.0625, 1e-12);
  // The same fan wound the other way faces down, against the input: a fold-over everywhere.
  EXPECT_NEAR(vrs::measure_against(fan(4, 4, 0.25, 2, 6, false), in, folds), 0.25 * area(above),
              1e-9);
  EXPECT_TRUE(folds);
  // Past `stop` the rest is not measured, and what is returned says so.
  const double stopped = vrs::measure_against(above, in, folds, 0.1 * area(above));
  EXPECT_GT(stopped, 0.1 * area(above));
  EXPECT_LT(stopped, 0.25 * area(above) - 1e-9);
}

TEST(LocalInput, MeasuresAsReadingEveryFaceDoesOnABumpyInput) {
  // Heights that make the nearest face of a point now near, now several faces away, and
  // fans tilted, raised and wound both ways: the shortcuts must find what every face gives.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> h(11 * 11);
  for (double& x : h)
    x = 0.6 * u(rng);
  vrs::LocalInput in;
  set_faces(in, grid(10, [&](int i, int j) { return h[size_t(i * 11 + j)]; }));
  int folded = 0, measured = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const vrs::Patch p = fan(5 + 2 * u(rng), 5 + 2 * u(rng), 0.8 * u(rng), 1 + 2 * (u(rng) + 1),
                             3 + trial % 9, trial % 4 != 0, 1.5 * u(rng));
    bool folds = false, folds_ref = false;
    double far = 0, far_ref = 0;
    const double got = vrs::measure_against(p, in, folds, HUGE_VAL, false, &far);
    const double want = brute_measure(p, in, folds_ref, far_ref);
    ASSERT_NEAR(got, want, 1e-12 * std::max(1.0, want)) << "trial " << trial;
    ASSERT_EQ(folds, folds_ref) << "trial " << trial;
    ASSERT_EQ(far, far_ref) << "trial " << trial;
    folded += folds;
    ++measured;
  }
  // Both answers occur, or the comparison proves little.
  EXPECT_GT(folded, 0);
  EXPECT_LT(folded, measured);
}

// The fin of InputSurface.AFinOnARidgeIsAFoldOver, asked of the input around it: the slide
// judges it as the run's plans do.
TEST(LocalInput, AFinOnARidgeIsAFoldOver) {
  vrs::LocalInput in;
  set_faces(in, grid(8, [](int i, int) { return 1.0 - 0.2 * std::abs(i - 4); }));
  auto one = [](Vec3 a, Vec3 b, Vec3 c) {
    vrs::Patch p;
    p.count = 1;
    p.tri[0] = {0, 1, 2};
    p.q[0] = a, p.q[1] = b, p.q[2] = c;
    return p;
  };
  const Vec3 a{4, 2, 1}, b{4, 6, 1}, apex{4 + 0.5 * std::tan(5 * M_PI / 180), 4, 1.5};
  for (const auto& [patch, folded] : {std::pair{one(a, b, apex), true},
                                      {one(a, apex, b), false},
                                      {one({1, 2, 0.4}, {3, 2, 0.8}, {2, 5, 0.6}), false}}) {
    bool folds = !folded, folds_ref = !folded;
    double far = 0, far_ref = 0;
    vrs::measure_against(patch, in, folds, HUGE_VAL, false, &far);
    brute_measure(patch, in, folds_ref, far_ref);
    EXPECT_EQ(folds, folded);
    EXPECT_EQ(folds_ref, folded);
  }
}

} // namespace
