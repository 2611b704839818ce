// The candidate fillings of a hole: the projection and the fan from each ring vertex.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include "fill/candidates.h"
#include "ring_case.h"
#include "test_meshes.h"

using namespace vrs;

namespace {

// Each new corner's data comes from a ring face that holds its vertex.
void expect_corner_faces_hold_their_vertex(const RingCase& h, const Patch& patch) {
  for (int t = 0; t < patch.count; ++t)
    for (int c = 0; c < 3; ++c) {
      const uint32_t f = h.ring.f[patch.from[t][c]], u = h.ring.v[patch.tri[t][c]];
      const uint32_t* tri = &h.mesh.triangles[3 * f];
      EXPECT_TRUE(tri[0] == u || tri[1] == u || tri[2] == u) << "triangle " << t << " corner " << c;
    }
}

} // namespace

TEST(Candidates, FanFromEachApexIsTheHalfEdgeCollapseOntoIt) {
  RingCase h;
  h.mesh = vrs_test::hexagon_fan();
  open_ring(h, 6);
  Patch patch = projected(h, 6, {0, 0, 1});
  ASSERT_EQ(h.ring.verts, 6);
  ASSERT_EQ(candidate_count(h.ring, true), 7);
  ASSERT_EQ(candidate_count(h.ring, false), 1);
  for (int apex = 0; apex < 6; ++apex) {
    ASSERT_TRUE(fill_candidate(h.ring, OpenRing::Border, 1 + apex, patch));
    ASSERT_EQ(patch.count, 4);
    // Every new triangle is an old one with v moved onto the apex: it holds the apex and one
    // ring edge away from it, and each such edge is used once.
    std::set<int> edges;
    for (int t = 0; t < patch.count; ++t) {
      const auto& tri = patch.tri[t];
      EXPECT_EQ(tri[0], apex);
      EXPECT_EQ(tri[2], (tri[1] + 1) % 6);
      edges.insert(tri[1]);
    }
    EXPECT_EQ(edges.size(), 4u);
    EXPECT_EQ(edges.count(apex), 0u);
    EXPECT_EQ(edges.count((apex + 5) % 6), 0u);
    expect_corner_faces_hold_their_vertex(h, patch);
  }
}

TEST(Candidates, OpenRingFanIsClosedByTheChord) {
  RingCase h;
  h.mesh = vrs_test::grid(2);
  open_ring(h, 1); // middle of the bottom border: an open ring
  Patch patch = projected(h, 1, {0, 0, 1});
  ASSERT_FALSE(h.ring.closed());
  const int k = h.ring.verts;
  ASSERT_TRUE(fill_candidate(h.ring, OpenRing::Border, 1, patch)); // fan from ring[0]
  ASSERT_EQ(patch.count, k - 2);
  // The last triangle closes the polygon: it holds the chord (ring[k - 1], ring[0]).
  const auto& last = patch.tri[patch.count - 1];
  EXPECT_EQ(last[0], 0);
  EXPECT_EQ(last[1], k - 2);
  EXPECT_EQ(last[2], k - 1);
  expect_corner_faces_hold_their_vertex(h, patch);
}

TEST(Candidates, ThreeVertexRingHasOneFanBesideTheProjection) {
  RingCase h;
  h.mesh = vrs_test::tetrahedron();
  open_ring(h, 0);
  ASSERT_EQ(h.ring.verts, 3);
  EXPECT_EQ(candidate_count(h.ring, true), 2);
}

TEST(Candidates, ProjectionRefusesARingThatFoldsOnThePlane) {
  RingCase h;
  h.mesh = vrs_test::hexagon_fan();
  open_ring(h, 6);
  Patch patch = projected(h, 6, {0, 0, 1});
  std::swap(patch.p[1], patch.p[2]); // ring no longer counter-clockwise around v
  EXPECT_FALSE(fill_candidate(h.ring, OpenRing::Border, 0, patch));
  EXPECT_TRUE(fill_candidate(h.ring, OpenRing::Border, 1, patch)); // fans need no projection
}

namespace {

// Every triangulation of the polygon i..j under the edge (i, j), as lists of triangles.
using Triangles = std::vector<std::array<int, 3>>;
void all_triangulations(int i, int j, std::vector<Triangles>& out) {
  out.clear();
  if (j - i < 2) {
    out.push_back({});
    return;
  }
  for (int m = i + 1; m < j; ++m) {
    std::vector<Triangles> left, right;
    all_triangulations(i, m, left);
    all_triangulations(m, j, right);
    for (const auto& l : left)
      for (const auto& r : right) {
        Triangles t = l;
        t.insert(t.end(), r.begin(), r.end());
        t.push_back({i, m, j});
        out.push_back(t);
      }
  }
}

// A made-up price per triangle (a < b < c), +inf for about one in five: deterministic.
double made_up_cost(int a, int b, int c, unsigned seed) {
  unsigned h =
      seed * 2654435761u ^ unsigned(a * 73856093) ^ unsigned(b * 19349663) ^ unsigned(c * 83492791);
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return h % 5 == 0 ? std::numeric_limits<double>::infinity() : double(h % 1000);
}

} // namespace

TEST(Candidates, LeastCostFillingIsTheBestOfEveryTriangulation) {
  // Against brute force: of all Catalan-many triangulations of rings of 4 to 9 vertices, with
  // made-up triangle prices (some refused) and some diagonals forbidden, the filling is one
  // whose worst triangle is least (then whose sum is), or none when every one is refused.
  int found = 0, none = 0;
  for (int k = 4; k <= 9; ++k)
    for (unsigned seed = 1; seed <= 40; ++seed) {
      Ring ring;
      ring.verts = ring.faces = k;
      auto cost = [&](int a, int b, int c) { return made_up_cost(a, b, c, seed); };
      auto diagonal_ok = [&](int a, int b) { return (a * 7 + b * 3 + int(seed)) % 6 != 0; };
      std::vector<Triangles> every;
      all_triangulations(0, k - 1, every);
      double best_worst = std::numeric_limits<double>::infinity(), best_sum = best_worst;
      for (const auto& t : every) {
        double worst = 0, sum = 0;
        bool allowed = true;
        for (const auto& x : t) {
          for (auto [a, b] : {std::pair{x[0], x[1]}, std::pair{x[1], x[2]}, std::pair{x[0], x[2]}})
            if (b - a >= 2 && !(a == 0 && b == k - 1)) allowed = allowed && diagonal_ok(a, b);
          worst = std::max(worst, cost(x[0], x[1], x[2]));
          sum += cost(x[0], x[1], x[2]);
        }
        if (!allowed || !(worst < std::numeric_limits<double>::infinity())) continue;
        if (worst < best_worst || (worst == best_worst && sum < best_sum))
          best_worst = worst, best_sum = sum;
      }
      Patch patch;
      const bool filled = fill_least_cost(ring, cost, diagonal_ok, patch);
      ASSERT_EQ(filled, best_worst < std::numeric_limits<double>::infinity())
          << "k " << k << " seed " << seed;
      if (!filled) {
        ++none;
        continue;
      }
      ++found;
      ASSERT_EQ(patch.count, k - 2);
      double worst = 0, sum = 0;
      std::set<std::pair<int, int>> edges;
      for (int t = 0; t < patch.count; ++t) {
        const auto& x = patch.tri[t];
        ASSERT_TRUE(x[0] < x[1] && x[1] < x[2]) << "counter-clockwise as the ring";
        worst = std::max(worst, cost(x[0], x[1], x[2]));
        sum += cost(x[0], x[1], x[2]);
        for (auto e : {std::pair<int, int>{x[0], x[1]}, {x[1], x[2]}, {x[0], x[2]}})
          edges.insert(e);
      }
      EXPECT_EQ(worst, best_worst) << "k " << k << " seed " << seed;
      EXPECT_EQ(sum, best_sum) << "k " << k << " seed " << seed;
      EXPECT_EQ(edges.size(), size_t(2 * k - 3)) << "a triangulation: k edges and k - 3 diagonals";
    }
  EXPECT_GT(found, 100);
  EXPECT_GT(none, 5); // the refusals do bite
}
