#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "evaluate/evaluation.h"
#include "test_meshes.h"

using namespace vrs;

namespace {

Evaluation evaluate(const Mesh& m, uint32_t v, Mode mode = Mode::Surface3D, bool line = false) {
  Topology t;
  t.build(m.triangles, m.vertex_count());
  Ring r;
  t.ring(v, m.triangles.data(), 64, r);
  Evaluator e(mode, mesh_plane_normal(m.positions.data(), m.triangles), m.positions.data());
  return e.evaluate(v, r, line);
}

// A closed fan of k neighbours on the unit circle (z = 0) around a centre at height h.
Mesh ring_fan(int k, float h) {
  Mesh m;
  for (int i = 0; i < k; ++i) {
    float a = 2 * 3.14159265f * float(i) / float(k);
    m.positions.insert(m.positions.end(), {std::cos(a), std::sin(a), 0.0f});
  }
  m.positions.insert(m.positions.end(), {0, 0, h});
  for (int i = 0; i < k; ++i)
    m.triangles.insert(m.triangles.end(), {uint32_t(k), uint32_t(i), uint32_t((i + 1) % k)});
  return m;
}

} // namespace

TEST(Evaluation, FlatFanHasZeroFactor) {
  Evaluation e = evaluate(vrs_test::hexagon_fan(), 6);
  EXPECT_NEAR(e.factor, 0.0, 1e-7);
  EXPECT_NEAR(e.normal.z, 1.0, 1e-9);
}

TEST(Evaluation, RaisedCentreFactorIsItsHeightOverThePlanarRing) {
  // All neighbour triples lie in z = 0, so the average plane is z = 0 and every neighbour is
  // h below the vertex along it.
  EXPECT_NEAR(evaluate(ring_fan(6, 0.25f), 6).factor, 0.25, 1e-6);
  EXPECT_NEAR(evaluate(ring_fan(9, -0.5f), 9).factor, 0.5, 1e-6);
}

TEST(Evaluation, SubsetOfTriplesAboveTheCapGivesTheSamePlaneOnAPlanarRing) {
  const int k = kAllTriplesValence + 8;
  Evaluation e = evaluate(ring_fan(k, 0.125f), k);
  EXPECT_NEAR(e.factor, 0.125, 1e-6);
  EXPECT_NEAR(e.normal.z, 1.0, 1e-9);
}

TEST(Evaluation, AveragePlaneFollowsATiltedRing) {
  Mesh m = ring_fan(7, 0.0f);
  // Tilt everything by 30 degrees about x: the factor of the flat fan stays zero.
  const float c = std::cos(0.5236f), s = std::sin(0.5236f);
  for (size_t i = 0; i < m.positions.size(); i += 3) {
    float y = m.positions[i + 1], z = m.positions[i + 2];
    m.positions[i + 1] = c * y - s * z;
    m.positions[i + 2] = s * y + c * z;
  }
  Evaluation e = evaluate(m, 7);
  EXPECT_NEAR(e.factor, 0.0, 1e-6);
  EXPECT_NEAR(e.normal.y, -s, 1e-6);
}

TEST(Evaluation, OrientationOfTheTriplesDoesNotCancel) {
  // The same fan with reversed faces: the plane normal flips with it, the factor does not.
  Mesh m = ring_fan(8, 0.3f);
  for (size_t i = 0; i < m.triangles.size(); i += 3)
    std::swap(m.triangles[i + 1], m.triangles[i + 2]);
  Evaluation e = evaluate(m, 8);
  EXPECT_NEAR(e.factor, 0.3, 1e-6);
  EXPECT_NEAR(e.normal.z, -1.0, 1e-9);
}

TEST(Evaluation, TerrainFactorIsTheMeanHeightDifference) {
  Mesh m = ring_fan(4, 1.0f);
  m.positions[2] = 0.5f; // one neighbour raised: differences 0.5, 1, 1, 1
  Evaluation e = evaluate(m, 4, Mode::Terrain25D);
  EXPECT_NEAR(e.factor, (0.5 + 3.0) / 4, 1e-6);
  EXPECT_EQ(e.normal.z, 1.0);
}

TEST(Evaluation, TwoNeighboursUseTheDistanceToTheirLine) {
  Mesh m;
  m.positions = {0, 0, 0, 2, 0, 0, 1, 0.75f, 0};
  m.triangles = {0, 1, 2};
  EXPECT_NEAR(evaluate(m, 2).factor, 0.75, 1e-6);
  EXPECT_NEAR(distance_to_line({1, 1, 1}, {0, 0, 0}, {0, 0, 5}), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(distance_to_line({1, 1, 1}, {0, 0, 0}, {0, 0, 0}), std::sqrt(3.0), 1e-12);
}

TEST(Evaluation, BoundaryLineDistanceRaisesTheFactorOfABentBoundary) {
  Mesh m = vrs_test::grid(2);
  m.positions[3 * 1 + 1] = -0.2f; // bend the bottom boundary at vertex 1 by 23°, in z = 0
  EXPECT_NEAR(evaluate(m, 1).factor, 0.0, 1e-6);
  EXPECT_NEAR(evaluate(m, 1, Mode::Surface3D, true).factor, 0.2, 1e-6);
}

TEST(Evaluation, BoundaryCornerIsKept) {
  Mesh m = vrs_test::grid(2);
  m.positions[3 * 1 + 1] = -0.6f; // a 62° turn: a corner of the outline
  EXPECT_TRUE(std::isinf(evaluate(m, 1, Mode::Surface3D, true).factor));
  EXPECT_TRUE(std::isinf(evaluate(m, 0, Mode::Surface3D, true).factor)); // the square's corner
}

TEST(Evaluation, NonFinitePositionGivesNoFactor) {
  Mesh m = ring_fan(6, 0.1f);
  m.positions[0] = NAN;
  EXPECT_TRUE(std::isinf(evaluate(m, 6).factor));
}

TEST(Evaluation, VertexNormalsOfASpherePointOutwardEvenAtHugeScale) {
  for (float scale : {1.0f, 3e37f}) {
    Mesh m = vrs_test::icosphere(2);
    for (float& p : m.positions)
      p *= scale;
    std::vector<float> n = vertex_normals(m.positions, m.triangles);
    for (size_t v = 0; v < m.vertex_count(); ++v) {
      Vec3 p{m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
      EXPECT_GT(dot(normalized(p), Vec3{n[4 * v], n[4 * v + 1], n[4 * v + 2]}), 0.99) << v;
      EXPECT_LT(n[4 * v + 3], 0.3f) << v; // a smooth surface's cone is narrow
    }
  }
}

TEST(Evaluation, VertexConesSumTheFacesInTheInputsOrderBitForBit) {
  // Vertex by vertex (what the threads share out), the sums are the ones a single pass over
  // the faces in order makes: float additions in the same order, the same bits.
  const std::string path = vrs_test::cgal_mesh("elephant.off");
  if (path.empty()) GTEST_FAIL() << "elephant.off missing: run scripts/setup.sh";
  const Mesh m = vrs_test::read_off(path);
  const size_t n = m.vertex_count();
  std::vector<float> sum(3 * n, 0.0f), area(n, 0.0f);
  auto at = [&](uint32_t v) {
    return Vec3{m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
  };
  for (size_t i = 0; i < m.triangles.size(); i += 3) {
    const Vec3 a = at(m.triangles[i]);
    const Vec3 c = cross(at(m.triangles[i + 1]) - a, at(m.triangles[i + 2]) - a);
    const Vec3 u = normalized(c);
    for (int k = 0; k < 3; ++k) {
      float* s = &sum[3 * size_t(m.triangles[i + k])];
      s[0] += float(u.x), s[1] += float(u.y), s[2] += float(u.z);
      area[m.triangles[i + k]] += float(0.5 * length(c));
    }
  }
  Topology topo;
  topo.build(m.triangles, n);
  const std::vector<float> cones = vertex_normals(m.positions, m.triangles);
  for (uint32_t v = 0; v < n; ++v) {
    float cone[4], fan_area = -1;
    vertex_cone(m.positions.data(), m.triangles.data(), topo, v, cone, &fan_area);
    const Vec3 u = normalized(Vec3{sum[3 * v], sum[3 * v + 1], sum[3 * v + 2]});
    ASSERT_EQ(cone[0], float(u.x)) << v;
    ASSERT_EQ(cone[1], float(u.y)) << v;
    ASSERT_EQ(cone[2], float(u.z)) << v;
    ASSERT_EQ(fan_area, area[v]) << v;
    for (int k = 0; k < 4; ++k)
      ASSERT_EQ(cone[k], cones[4 * v + k]) << v;
  }
}

TEST(Evaluation, TripleSubsetStaysCloseToAllTriplesOnARealMesh) {
  // Measures what the subset above the cap costs: on armadillo (CGAL data), for every vertex
  // of valence 5..10, the factor from the 2k-triple subset against the one from all triples.
  const std::string path = vrs_test::cgal_mesh("armadillo.off");
  if (path.empty()) GTEST_FAIL() << "armadillo.off missing: run scripts/setup.sh";
  Mesh m = vrs_test::read_off(path);
  Topology t;
  t.build(m.triangles, m.vertex_count());
  Evaluator all(Mode::Surface3D, {0, 0, 1}, m.positions.data(), kMaxRing);
  Evaluator subset(Mode::Surface3D, {0, 0, 1}, m.positions.data(), 0);
  double sum_rel = 0, worst_angle = 0;
  size_t n = 0;
  Ring r;
  for (uint32_t v = 0; v < m.vertex_count(); ++v) {
    if (t.ring(v, m.triangles.data(), 10, r) != VertexKind::Interior || r.verts < 5) continue;
    Evaluation a = all.evaluate(v, r, false), b = subset.evaluate(v, r, false);
    if (!(a.factor > 0)) continue;
    sum_rel += std::fabs(b.factor - a.factor) / a.factor;
    worst_angle = std::max(worst_angle, std::acos(std::min(1.0, dot(a.normal, b.normal))));
    ++n;
  }
  ASSERT_GT(n, 20000u);
  const double mean_rel = sum_rel / double(n);
  std::printf("triple subset vs all triples, %zu vertices: mean |dfactor|/factor %.4f, "
              "worst normal angle %.2f deg\n",
              n, mean_rel, worst_angle * 180 / M_PI);
  EXPECT_LT(mean_rel, 0.1);
}
