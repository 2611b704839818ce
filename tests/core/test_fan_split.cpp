// Vertices where several fans meet (fan_split.h): split into a copy a fan for the run, one
// vertex again on output, and never joined by an edge that would give an edge a third face.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "mesh/fan_split.h"
#include "mesh/topology.h"
#include "mesh_checks.h"
#include "test_meshes.h"

using namespace vrs;

namespace {

size_t kind_count(const Mesh& m, VertexKind kind) {
  Topology t;
  t.build(m.triangles, m.vertex_count());
  Ring r;
  size_t count = 0;
  for (uint32_t v = 0; v < m.vertex_count(); ++v)
    count += t.ring(v, m.triangles.data(), kMaxRing, r) == kind;
  return count;
}

Options ratio(double r) {
  Options o;
  o.target.ratio = r;
  o.corner_sources = true;
  return o;
}

} // namespace

TEST(FanSplit, EachFanOfAVertexGetsItsOwnCopyAndTheCopiesKnowEachOther) {
  // Two cones on one apex (closed fans) and, beside it, a bow tie (two open fans).
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 1, -1, 0, 1, 0, 1, 1, 1, 0, -1, -1, 0, -1, 0, -1, -1};
  m.triangles = {0, 1, 3, 0, 3, 2, 0, 2, 1, 0, 4, 6, 0, 6, 5, 0, 5, 4};
  Topology topo;
  topo.build(m.triangles, m.vertex_count());
  Ring ring;
  ASSERT_EQ(topo.ring(0, m.triangles.data(), kMaxRing, ring), VertexKind::NonManifold);
  const FanSplit split = split_fans(m.triangles, m.vertex_count(), topo, {0});
  ASSERT_EQ(split.original, std::vector<uint32_t>{0});
  EXPECT_EQ(split.sibling[0], 7u);
  EXPECT_EQ(split.sibling[7], 0u);
  EXPECT_EQ(split.sibling[3], kNone);
  // The first fan keeps the vertex, the second names the copy.
  for (size_t f = 0; f < 6; ++f)
    EXPECT_EQ(m.triangles[3 * f], f < 3 ? 0u : 7u) << "face " << f;
  m.positions.insert(m.positions.end(), {0, 0, 0});
  topo.build(m.triangles, m.vertex_count());
  EXPECT_EQ(topo.ring(0, m.triangles.data(), kMaxRing, ring), VertexKind::Interior);
  EXPECT_EQ(topo.ring(7, m.triangles.data(), kMaxRing, ring), VertexKind::Interior);
  // On output they are one vertex: an edge from a copy is an edge from the others.
  topo.set_siblings(&split.sibling);
  EXPECT_TRUE(topo.has_edge(0, 4, m.triangles.data()));
  EXPECT_TRUE(topo.has_edge(7, 1, m.triangles.data()));
  EXPECT_TRUE(topo.has_edge(0, 7, m.triangles.data()));
  EXPECT_FALSE(topo.has_edge(1, 4, m.triangles.data()));

  Mesh bow;
  bow.positions = {0, 0, 0, 1, 1, 0, 1, -1, 0, -1, 1, 0, -1, -1, 0};
  bow.triangles = {0, 2, 1, 0, 3, 4};
  topo.build(bow.triangles, bow.vertex_count());
  const FanSplit b = split_fans(bow.triangles, bow.vertex_count(), topo, {0});
  EXPECT_EQ(b.original, std::vector<uint32_t>{0});
  EXPECT_EQ(bow.triangles[3], 5u);
}

TEST(FanSplit, AnEdgeOfThreeFacesOrFacesWalkingAnEdgeAlikeStayAsTheyAre) {
  Mesh fin = vrs_test::tetrahedron();
  const uint32_t a = fin.triangles[0], b = fin.triangles[1];
  fin.positions.insert(fin.positions.end(), {3, 3, 3});
  fin.triangles.insert(fin.triangles.end(), {a, b, uint32_t(fin.vertex_count() - 1)});
  Topology topo;
  topo.build(fin.triangles, fin.vertex_count());
  const Mesh before = fin;
  EXPECT_TRUE(split_fans(fin.triangles, fin.vertex_count(), topo, {a, b}).empty());
  EXPECT_EQ(fin.triangles, before.triangles);
}

TEST(FanSplit, ACrackedMeshSimplifiesThroughItsCracksAndEachVertexComesOutOnce) {
  const Mesh in = vrs_test::cracked_cylinder(5, 4, 16);
  ASSERT_EQ(kind_count(in, VertexKind::NonManifold), 4u * 16u); // every other crack vertex
  for (double r : {0.1, 0.05}) { // five open tubes: 30 faces at least
    const Options o = ratio(r);
    Mesh m = in;
    const Report rep = simplify(m, o);
    ASSERT_EQ(vrs_test::check_run(in, m, o, rep), "") << r;
    EXPECT_TRUE(rep.target_reached) << r << ": " << rep.stop_detail;
    EXPECT_EQ(rep.kept_nonmanifold, 0u) << r;
    EXPECT_EQ(vrs_test::edge_stats(m).nonmanifold, 0u) << r;
    // Each input vertex at most once (every input position differs), and the count of
    // removals is of input vertices.
    std::set<std::array<float, 3>> at;
    for (size_t v = 0; v < m.vertex_count(); ++v)
      at.insert({m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]});
    EXPECT_EQ(at.size(), m.vertex_count()) << r;
    EXPECT_EQ(rep.removed, in.vertex_count() - m.vertex_count()) << r;
    // The same output on any thread count, and by parts.
    for (int threads : {2, 3}) {
      Options t = o;
      t.threads = threads;
      Mesh again = in;
      simplify(again, t);
      EXPECT_TRUE(vrs_test::same_bits(m, again)) << r << ", " << threads << " threads";
    }
    Options parts = o;
    parts.tuning.part_vertices = 32;
    parts.tuning.lazy_from_faces = 0; // the parts run with lazy prices only
    Mesh p1 = in, p2 = in;
    const Report rp = simplify(p1, parts);
    ASSERT_EQ(vrs_test::check_run(in, p1, parts, rp), "") << r << " by parts";
    EXPECT_EQ(vrs_test::edge_stats(p1).nonmanifold, 0u) << r << " by parts";
    parts.threads = 2;
    simplify(p2, parts);
    EXPECT_TRUE(vrs_test::same_bits(p1, p2)) << r << " by parts, 2 threads";
  }
}

TEST(FanSplit, AVertexBothOfWhoseFansKeepItIsOneVertexWithBoth) {
  // Lightly simplified, most crack vertices stay in both bands: one output vertex each,
  // its faces on both sides.
  const Mesh in = vrs_test::cracked_cylinder(5, 4, 16);
  Mesh m = in;
  const Options o = ratio(0.9);
  const Report rep = simplify(m, o);
  ASSERT_EQ(vrs_test::check_run(in, m, o, rep), "");
  EXPECT_GT(kind_count(m, VertexKind::NonManifold), 0u);
  EXPECT_EQ(vrs_test::edge_stats(m).nonmanifold, 0u);
  // Split, the cracks' 64 vertices are 128 border vertices: the border is simplified (it
  // would take too much of the target), and the copies of a vertex are not a seam of split
  // vertices kept as one (Simplifier::lock_split_seams).
  EXPECT_TRUE(rep.boundary_simplified);
  EXPECT_LT(rep.kept_boundary, 64u);
  EXPECT_EQ(m.vertex_count() + rep.removed, in.vertex_count());
}

TEST(FanSplit, TwoConesOnOneApexPastTheValenceCapAreSplitToo) {
  // Each cone's apex has 20 faces, the shared one 40 (past max_valence 32): kept whole before,
  // a copy a cone now, each of 20.
  Mesh m;
  m.positions = {0, 0, 0};
  const int n = 20;
  for (int side : {1, -1}) {
    const uint32_t first = uint32_t(m.vertex_count());
    for (int i = 0; i < n; ++i) {
      const float a = 2 * 3.14159265f * float(i) / float(n);
      m.positions.insert(m.positions.end(), {std::cos(a), std::sin(a), float(side)});
    }
    m.positions.insert(m.positions.end(), {0, 0, 1.2f * float(side)}); // the base's centre
    const uint32_t centre = uint32_t(m.vertex_count() - 1);
    for (int i = 0; i < n; ++i) {
      const uint32_t a = first + uint32_t(i), b = first + uint32_t((i + 1) % n);
      if (side > 0)
        m.triangles.insert(m.triangles.end(), {0, b, a, centre, a, b});
      else
        m.triangles.insert(m.triangles.end(), {0, a, b, centre, b, a});
    }
  }
  const Options o = ratio(0.5);
  Mesh out = m;
  const Report rep = simplify(out, o);
  ASSERT_EQ(vrs_test::check_run(m, out, o, rep), "");
  EXPECT_EQ(rep.kept_high_valence, 0u);
  EXPECT_EQ(rep.kept_nonmanifold, 0u);
  EXPECT_TRUE(rep.target_reached) << rep.stop_detail;
  EXPECT_EQ(vrs_test::edge_stats(out).nonmanifold, 0u);
}
