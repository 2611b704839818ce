#include <gtest/gtest.h>

#include "mesh/topology.h"
#include "test_meshes.h"

using namespace vrs;

namespace {

VertexKind kind_of(const Mesh& m, uint32_t v, Ring& r, int cap = 32) {
  Topology t;
  t.build(m.triangles, m.vertex_count());
  return t.ring(v, m.triangles.data(), cap, r);
}

} // namespace

TEST(Topology, InteriorRingIsClosedAndCounterClockwise) {
  Mesh m = vrs_test::hexagon_fan();
  Ring r;
  ASSERT_EQ(kind_of(m, 6, r), VertexKind::Interior);
  ASSERT_EQ(r.verts, 6);
  ASSERT_EQ(r.faces, 6);
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ(r.v[(i + 1) % 6], (r.v[i] + 1) % 6);
}

TEST(Topology, BoundaryRingIsOpenWithBoundaryNeighboursAtTheEnds) {
  Mesh m = vrs_test::grid(2); // 3 x 3 vertices; vertex 1 is mid-bottom
  Ring r;
  ASSERT_EQ(kind_of(m, 1, r), VertexKind::Boundary);
  EXPECT_EQ(r.verts, r.faces + 1);
  EXPECT_EQ(r.v[0], 2u); // walking counter-clockwise from the right neighbour
  EXPECT_EQ(r.v[r.verts - 1], 0u);
}

TEST(Topology, SingleTriangleVertexIsCorner) {
  Mesh m = vrs_test::grid(1);
  Ring r;
  EXPECT_EQ(kind_of(m, 1, r), VertexKind::Corner);
}

TEST(Topology, EdgeWithThreeFacesIsNonManifold) {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
  m.triangles = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  Ring r;
  EXPECT_EQ(kind_of(m, 0, r), VertexKind::NonManifold);
  EXPECT_EQ(kind_of(m, 1, r), VertexKind::NonManifold);
}

TEST(Topology, TwoFansSharingAVertexAreNonManifold) {
  Mesh m; // bow tie: two triangles touching at vertex 0
  m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, -1, 0};
  m.triangles = {0, 1, 2, 0, 3, 4};
  Ring r;
  EXPECT_EQ(kind_of(m, 0, r), VertexKind::NonManifold);
}

TEST(Topology, InconsistentOrientationIsNonManifold) {
  Mesh m = vrs_test::hexagon_fan();
  std::swap(m.triangles[1], m.triangles[2]); // flip one face
  Ring r;
  EXPECT_EQ(kind_of(m, 6, r), VertexKind::NonManifold);
}

TEST(Topology, ValenceAboveTheCapIsHighValence) {
  Mesh m = vrs_test::hexagon_fan();
  Ring r;
  EXPECT_EQ(kind_of(m, 6, r, 5), VertexKind::HighValence);
  EXPECT_EQ(kind_of(m, 6, r, 6), VertexKind::Interior);
}

TEST(Topology, AddAndRemoveFacesGrowTheSliceAndKeepOrder) {
  Mesh m = vrs_test::tetrahedron();
  Topology t;
  t.build(m.triangles, m.vertex_count());
  for (uint32_t f = 100; f < 140; ++f)
    t.add_face(0, f);
  ASSERT_EQ(t.valence(0), 43u);
  t.remove_face(0, 120);
  ASSERT_EQ(t.valence(0), 42u);
  const uint32_t* s = t.faces_of(0);
  for (uint32_t i = 3; i + 1 < 42; ++i)
    EXPECT_LT(s[i], s[i + 1]);
  EXPECT_EQ(t.valence(1), 3u); // neighbours' slices untouched by the move
}

TEST(Topology, EdgeAndTriangleQueries) {
  Mesh m = vrs_test::tetrahedron();
  Topology t;
  t.build(m.triangles, m.vertex_count());
  EXPECT_TRUE(t.has_edge(0, 3, m.triangles.data()));
  EXPECT_TRUE(t.has_triangle(1, 2, 3, m.triangles.data()));
  EXPECT_TRUE(t.has_triangle(3, 2, 1, m.triangles.data())); // either orientation
  Mesh g = vrs_test::grid(1);
  t.build(g.triangles, g.vertex_count());
  EXPECT_FALSE(t.has_edge(1, 2, g.triangles.data())); // the other diagonal
}
