#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fill/triangulation.h"

using namespace vrs;

namespace {

const Vec3 kUp{0, 0, 1};

double polygon_area2(const std::vector<Vec2>& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i)
    a += orient2d({0, 0}, p[i], p[(i + 1) % p.size()]);
  return a;
}

// Every triangle counter-clockwise and their areas add up to the polygon's: a triangulation
// of the polygon with no overlap and no gap.
void expect_tiles(const std::vector<Vec2>& p, const Patch& t) {
  ASSERT_EQ(t.count, int(p.size()) - 2);
  double sum = 0;
  for (int i = 0; i < t.count; ++i) {
    double a = orient2d(p[t.tri[i][0]], p[t.tri[i][1]], p[t.tri[i][2]]);
    EXPECT_GT(a, 0) << "triangle " << i;
    sum += a;
  }
  EXPECT_NEAR(sum, polygon_area2(p), 1e-9 * std::fabs(polygon_area2(p)));
}

std::vector<Vec3> lift(const std::vector<Vec2>& p) {
  std::vector<Vec3> q;
  for (auto v : p)
    q.push_back({v.x, v.y, 0});
  return q;
}

} // namespace

TEST(Triangulation, ConvexPolygonGetsAFanFromItsBestApex) {
  // A long thin hexagon: the fan from an end vertex makes slivers, from a middle one it does not.
  std::vector<Vec2> p = {{0, 0}, {4, -1}, {8, 0}, {8, 1}, {4, 2}, {0, 1}};
  ASSERT_TRUE(is_convex(p.data(), 6));
  Patch t;
  auto q = lift(p);
  triangulate_fan(p.data(), q.data(), kUp, 6, t);
  expect_tiles(p, t);
  EXPECT_TRUE(t.tri[0][0] == 1 || t.tri[0][0] == 4);
}

TEST(Triangulation, ConcavePolygonIsEarClipped) {
  std::vector<Vec2> p = {{2, 0}, {2, 2}, {0, 3}, {-0.3, 1.2}, {-2, 2}, {-2, 0}};
  ASSERT_FALSE(is_convex(p.data(), 6));
  Patch t;
  auto q = lift(p);
  ASSERT_TRUE(triangulate_ears(p.data(), q.data(), kUp, 6, t));
  expect_tiles(p, t);
}

TEST(Triangulation, RandomStarShapedPolygonsAreTiled) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> radius(0.2, 1.0);
  for (int trial = 0; trial < 500; ++trial) {
    int k = 3 + trial % 20;
    std::vector<Vec2> p;
    for (int i = 0; i < k; ++i) {
      double a = 2 * M_PI * (i + 0.5 * radius(rng)) / k, r = radius(rng);
      p.push_back({r * std::cos(a), r * std::sin(a)});
    }
    Patch t;
    auto q = lift(p);
    ASSERT_TRUE(triangulate_ears(p.data(), q.data(), kUp, k, t)) << "trial " << trial;
    expect_tiles(p, t);
  }
}

TEST(Triangulation, EarClippingRefusesAPolygonWithNoEar) {
  // Clockwise square: no convex corner, so no ear.
  std::vector<Vec2> p = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  Patch t;
  auto q = lift(p);
  EXPECT_FALSE(triangulate_ears(p.data(), q.data(), kUp, 4, t));
}

TEST(Triangulation, ScorePrefersTrianglesFacingTheProjectionNormal) {
  // Same shape, one lying in the plane, one standing across it: only the first scores.
  Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0.5, 0.8, 0}, d{0.5, 0, 0.8};
  EXPECT_GT(triangle_score(a, b, c, kUp), 0.9);
  EXPECT_NEAR(triangle_score(a, b, d, kUp), 0.0, 1e-12);
  EXPECT_EQ(triangle_score(a, c, b, kUp), 0.0); // facing away
}
