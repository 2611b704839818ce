// 2D planar and 2.5D terrain meshes.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh_checks.h"
#include "test_meshes.h"

using namespace vrs;

namespace {

// Signed area of every face projected along unit direction n: all must be positive (no fold)
// and they must add up to the domain's area (no overlap).
void expect_projection_tiles(const Mesh& m, const double n[3], double domain_area) {
  double sum = 0;
  for (size_t i = 0; i < m.triangles.size(); i += 3) {
    const float* a = &m.positions[3 * m.triangles[i]];
    const float* b = &m.positions[3 * m.triangles[i + 1]];
    const float* c = &m.positions[3 * m.triangles[i + 2]];
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double x[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    double s = 0.5 * (x[0] * n[0] + x[1] * n[1] + x[2] * n[2]);
    EXPECT_GT(s, 0) << "face " << i / 3 << " folds over";
    sum += s;
  }
  EXPECT_NEAR(sum, domain_area, 1e-4 * domain_area);
}

} // namespace

TEST(Modes, PlanarMeshInAnyPlaneKeepsItsBoundaryAndDoesNotFold) {
  Mesh in = vrs_test::grid(30, 0.3f); // a jittered FEM-like triangulation
  // Tilt the plane: planar mode must find it by itself.
  const double c = std::cos(0.7), s = std::sin(0.7);
  for (size_t i = 0; i < in.positions.size(); i += 3) {
    float y = in.positions[i + 1];
    in.positions[i + 1] = float(c * y);
    in.positions[i + 2] = float(s * y);
  }
  Mesh m = in;
  Options o;
  o.mode = Mode::Planar2D;
  o.target.ratio = 0.2;
  o.simplify_boundary_when_needed = false; // the paper's rule: the border stays
  Report r = simplify(m, o);
  ASSERT_TRUE(r.ok);
  EXPECT_TRUE(r.target_reached);
  EXPECT_EQ(vrs_test::check_subset(in, m, r), "");
  EXPECT_EQ(vrs_test::check_boundary_kept(in, m, r), "");
  const double normal[3] = {0, -s, c};
  expect_projection_tiles(m, normal, 900.0);
}

TEST(Modes, TerrainStaysAHeightField) {
  const Mesh in = vrs_test::terrain(64);
  for (double ratio : {0.3, 0.05}) {
    Mesh m = in;
    Options o;
    o.mode = Mode::Terrain25D;
    o.target.ratio = ratio;
    o.simplify_boundary_when_needed = false; // the paper's rule: the border stays
    Report r = simplify(m, o);
    ASSERT_TRUE(r.ok);
    EXPECT_TRUE(r.target_reached) << m.face_count();
    EXPECT_EQ(vrs_test::check_subset(in, m, r), "");
    EXPECT_EQ(vrs_test::check_boundary_kept(in, m, r), "");
    const double up[3] = {0, 0, 1};
    expect_projection_tiles(m, up, 64.0 * 64.0);
  }
}

TEST(Modes, TerrainKeepsASpikeBeforeTheSmoothParts) {
  // The paper's 2.5D factor is the mean height difference to the neighbours: a spike has the
  // largest and outlives everything smooth around it.
  Mesh in = vrs_test::terrain(64);
  const uint32_t spike = 20 * 65 + 45;
  in.positions[3 * spike + 2] += 10.0f;
  Mesh m = in;
  Options o;
  o.mode = Mode::Terrain25D;
  o.target.ratio = 0.05;
  Report r = simplify(m, o);
  EXPECT_TRUE(r.target_reached);
  EXPECT_NE(r.remap[spike], kRemoved);
}
