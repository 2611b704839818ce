// The benchmark's surface-error measure against cases with a known answer.
#include <gtest/gtest.h>

#include <cmath>

#include "surface_error.h"
#include "test_meshes.h"

using vrs_bench::surface_error;

namespace {

vrs::Mesh scaled(vrs::Mesh m, float s) {
  for (float& p : m.positions)
    p *= s;
  return m;
}

} // namespace

TEST(SurfaceError, SameMeshIsZero) {
  const vrs::Mesh m = vrs_test::icosphere(3);
  auto e = surface_error(m, m, 20000);
  EXPECT_LT(e.max, 1e-6); // float rounding of the closest-point query only
  EXPECT_LT(e.mean, 1e-7);
  EXPECT_GT(e.samples, 40000u);
}

TEST(SurfaceError, SphereAgainstAScaledSphereIsTheRadiusDifference) {
  // Two concentric spheres of radius 1 and 1.02, finely tessellated: every point of one is
  // 0.02 from the other (up to the facets' sag, ~1e-4 here), in both directions.
  const vrs::Mesh a = vrs_test::icosphere(5), b = scaled(a, 1.02f);
  auto e = surface_error(a, b, 100000);
  const double diag = e.diagonal, expected = 0.02 / diag;
  EXPECT_NEAR(diag, 2 * std::sqrt(3.0), 0.01);
  EXPECT_NEAR(e.max, expected, 0.05 * expected);
  EXPECT_NEAR(e.mean, expected, 0.05 * expected);
  EXPECT_NEAR(e.rms, expected, 0.05 * expected);
}

TEST(SurfaceError, IsSymmetricWhereOneSideMissesAPart) {
  // A square against its left half: from the half everything is on the square (0), from the
  // square the right part is up to half a side away. The symmetric max must see that.
  vrs::Mesh full = vrs_test::grid(8), half;
  half.positions = full.positions;
  for (size_t i = 0; i < full.triangles.size(); i += 3) {
    bool left = true;
    for (int k = 0; k < 3; ++k)
      left = left && full.positions[3 * full.triangles[i + k]] <= 4.0f;
    if (left)
      half.triangles.insert(half.triangles.end(), &full.triangles[i], &full.triangles[i] + 3);
  }
  auto e = surface_error(full, half, 50000);
  EXPECT_NEAR(e.max * e.diagonal, 4.0, 0.05);
  // From the square, half the samples are 0 away and half uniformly 0..4 (mean 1); from the
  // half, all are 0: pooled over equal sample counts, 0.5.
  EXPECT_NEAR(e.mean * e.diagonal, 0.5, 0.03);
}

// The fold-over share: none on the mesh itself, all of it with every face turned over, and the
// turned-over faces' share of the area when only some are.
TEST(FoldOverShare, CountsTheAreaFacingAgainstTheNearestInputFace) {
  const vrs::Mesh m = vrs_test::icosphere(3);
  EXPECT_EQ(vrs_bench::fold_over_share(m, m, 20000), 0.0);
  vrs::Mesh flipped = m;
  for (size_t f = 0; f < flipped.face_count(); ++f)
    std::swap(flipped.triangles[3 * f + 1], flipped.triangles[3 * f + 2]);
  EXPECT_EQ(vrs_bench::fold_over_share(m, flipped, 20000), 1.0);
  vrs::Mesh half = m; // every other face turned over: about half the area
  for (size_t f = 0; f < half.face_count(); f += 2)
    std::swap(half.triangles[3 * f + 1], half.triangles[3 * f + 2]);
  EXPECT_NEAR(vrs_bench::fold_over_share(m, half, 20000), 0.5, 0.05);
}

TEST(FoldOverShare, AnInputInRandomOrientationIsReadCoherently) {
  // A sphere written one face in three reversed stands for the sphere: the coherent sphere
  // folds nowhere against it, the sphere turned inside out everywhere. (Read as written, a
  // third of either would count as folded.)
  const vrs::Mesh m = vrs_test::icosphere(3);
  vrs::Mesh shuffled = m, inside_out = m;
  for (size_t f = 0; f < shuffled.face_count(); f += 3)
    std::swap(shuffled.triangles[3 * f + 1], shuffled.triangles[3 * f + 2]);
  for (size_t f = 0; f < inside_out.face_count(); ++f)
    std::swap(inside_out.triangles[3 * f + 1], inside_out.triangles[3 * f + 2]);
  EXPECT_EQ(vrs_bench::fold_over_share(shuffled, m, 20000), 0.0);
  EXPECT_EQ(vrs_bench::fold_over_share(shuffled, inside_out, 20000), 1.0);
}
