// The candidate fillings of a hole: the projection and the fan from each ring vertex.
#include <gtest/gtest.h>

#include <set>

#include "candidates.h"
#include "test_meshes.h"

using namespace vrs;

namespace {

struct Hole {
  Mesh mesh;
  Topology topo;
  Ring ring;
  Patch patch;
};

// The ring of `v`, projected on the z = 0 plane.
void open_hole(Hole& h, uint32_t v) {
  h.topo.build(h.mesh.triangles, h.mesh.vertex_count());
  h.topo.ring(v, h.mesh.triangles.data(), 64, h.ring);
  plane_basis({0, 0, 1}, h.patch.u, h.patch.w);
  h.patch.normal = {0, 0, 1};
  const float* p = h.mesh.positions.data();
  for (int i = 0; i < h.ring.verts; ++i) {
    const uint32_t u = h.ring.v[i];
    h.patch.q[i] = {p[3 * u], p[3 * u + 1], p[3 * u + 2]};
    Vec3 d = h.patch.q[i] - Vec3{p[3 * v], p[3 * v + 1], p[3 * v + 2]};
    h.patch.p[i] = {dot(d, h.patch.u), dot(d, h.patch.w)};
  }
}

// Each new corner's data comes from a ring face that holds its vertex.
void expect_corner_faces_hold_their_vertex(const Hole& h) {
  for (int t = 0; t < h.patch.count; ++t)
    for (int c = 0; c < 3; ++c) {
      const uint32_t f = h.ring.f[h.patch.from[t][c]], u = h.ring.v[h.patch.tri[t][c]];
      const uint32_t* tri = &h.mesh.triangles[3 * f];
      EXPECT_TRUE(tri[0] == u || tri[1] == u || tri[2] == u) << "triangle " << t << " corner " << c;
    }
}

} // namespace

TEST(Candidates, FanFromEachApexIsTheHalfEdgeCollapseOntoIt) {
  Hole h;
  h.mesh = vrs_test::hexagon_fan();
  open_hole(h, 6);
  ASSERT_EQ(h.ring.verts, 6);
  ASSERT_EQ(candidate_count(h.ring, true), 7);
  ASSERT_EQ(candidate_count(h.ring, false), 1);
  for (int apex = 0; apex < 6; ++apex) {
    ASSERT_TRUE(fill_candidate(h.ring, OpenRing::Border, 1 + apex, h.patch));
    ASSERT_EQ(h.patch.count, 4);
    // Every new triangle is an old one with v moved onto the apex: it holds the apex and one
    // ring edge away from it, and each such edge is used once.
    std::set<int> edges;
    for (int t = 0; t < h.patch.count; ++t) {
      const auto& tri = h.patch.tri[t];
      EXPECT_EQ(tri[0], apex);
      EXPECT_EQ(tri[2], (tri[1] + 1) % 6);
      edges.insert(tri[1]);
    }
    EXPECT_EQ(edges.size(), 4u);
    EXPECT_EQ(edges.count(apex), 0u);
    EXPECT_EQ(edges.count((apex + 5) % 6), 0u);
    expect_corner_faces_hold_their_vertex(h);
  }
}

TEST(Candidates, OpenRingFanIsClosedByTheChord) {
  Hole h;
  h.mesh = vrs_test::grid(2);
  open_hole(h, 1); // middle of the bottom border: an open ring
  ASSERT_FALSE(h.ring.closed());
  const int k = h.ring.verts;
  ASSERT_TRUE(fill_candidate(h.ring, OpenRing::Border, 1, h.patch)); // fan from ring[0]
  ASSERT_EQ(h.patch.count, k - 2);
  // The last triangle closes the polygon: it holds the chord (ring[k - 1], ring[0]).
  const auto& last = h.patch.tri[h.patch.count - 1];
  EXPECT_EQ(last[0], 0);
  EXPECT_EQ(last[1], k - 2);
  EXPECT_EQ(last[2], k - 1);
  expect_corner_faces_hold_their_vertex(h);
}

TEST(Candidates, ThreeVertexRingHasOneFanBesideTheProjection) {
  Hole h;
  h.mesh = vrs_test::tetrahedron();
  open_hole(h, 0);
  ASSERT_EQ(h.ring.verts, 3);
  EXPECT_EQ(candidate_count(h.ring, true), 2);
}

TEST(Candidates, ProjectionRefusesARingThatFoldsOnThePlane) {
  Hole h;
  h.mesh = vrs_test::hexagon_fan();
  open_hole(h, 6);
  std::swap(h.patch.p[1], h.patch.p[2]); // ring no longer counter-clockwise around v
  EXPECT_FALSE(fill_candidate(h.ring, OpenRing::Border, 0, h.patch));
  EXPECT_TRUE(fill_candidate(h.ring, OpenRing::Border, 1, h.patch)); // fans need no projection
}
