// The candidate fillings of a hole: the projection and the fan from each ring vertex.
#include <gtest/gtest.h>

#include <set>

#include "candidates.h"
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
