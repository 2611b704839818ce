// The certified error bound (Options::max_error, core/src/evaluate/error_bound.cpp): exact on cases
// whose Hausdorff distance is known, a bound on real meshes (every removed input vertex within it
// of the output, measured exactly), and what stops the run.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "evaluate/local_error.h"
#include "mesh_checks.h"
#include "test_meshes.h"

using namespace vrs;

namespace {

Options bounded(double max_error, size_t faces = 0) {
  Options o;
  o.target.kind = TargetKind::Faces;
  o.target.faces = faces;
  o.max_error = max_error;
  return o;
}

Vec3 at(const Mesh& m, uint32_t v) {
  return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
}

// Largest distance from a removed input vertex to the output surface (exact, brute force):
// a lower bound of the Hausdorff distance the report's bound must cover.
double farthest_removed(const Mesh& in, const Mesh& out, const Report& r) {
  double worst = 0;
  for (uint32_t v = 0; v < in.vertex_count(); ++v) {
    if (r.remap[v] != kRemoved) continue;
    double d = HUGE_VAL;
    for (size_t f = 0; f < out.triangles.size(); f += 3)
      d = std::min(d, point_triangle_distance(at(in, v), at(out, out.triangles[f]),
                                              at(out, out.triangles[f + 1]),
                                              at(out, out.triangles[f + 2])));
    worst = std::max(worst, d);
  }
  return worst;
}

} // namespace

TEST(ErrorBound, FlatRegionsCertifyZero) {
  const Mesh in = vrs_test::grid(12, 0.2f);
  Mesh out = in;
  Options o = bounded(std::numeric_limits<double>::infinity());
  o.target.kind = TargetKind::Ratio;
  o.target.ratio = 0.3;
  const Report r = simplify(out, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_GT(r.removed, 0u);
  EXPECT_LT(r.error_bound, 1e-12); // rounding only
}

TEST(ErrorBound, TentApexIsExactlyItsDrop) {
  // The centre of a hexagon raised by h: removing it leaves the flat hexagon, whose Hausdorff
  // distance to the tent is h, at the apex.
  const float h = 0.25f;
  const Mesh in = vrs_test::hexagon_fan(h);
  Mesh out = in;
  const Report r = simplify(out, bounded(std::numeric_limits<double>::infinity()));
  ASSERT_TRUE(r.ok) << r.message;
  ASSERT_EQ(r.removed, 1u);
  EXPECT_NEAR(r.error_bound, h, 1e-6);
  EXPECT_NEAR(farthest_removed(in, out, r), h, 1e-6);
}

TEST(ErrorBound, TooSmallABoundKeepsTheTent) {
  const Mesh in = vrs_test::hexagon_fan(0.25f);
  Mesh out = in;
  const Report r = simplify(out, bounded(0.2));
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.removed, 0u);
  EXPECT_EQ(r.stop, StopReason::ErrorBound);
  EXPECT_TRUE(r.target_reached);
  EXPECT_GT(r.rejected[RejectBound], 0u);
  EXPECT_NE(r.stop_detail.find("error_bound"), std::string::npos) << r.stop_detail;
  EXPECT_EQ(r.stop_cause, StopCause::ErrorBound);
}

TEST(ErrorBound, RealMeshesStayWithinTheBoundTheyCertify) {
  for (const char* name : {"elephant", "fandisk", "mushroom", "bunny00"}) {
    const std::string path = vrs_test::cgal_mesh(std::string(name) + ".off");
    if (path.empty()) GTEST_SKIP() << "CGAL data set missing";
    const Mesh in = vrs_test::read_off(path);
    const double diag = bounding_box_diagonal(in);
    for (double fraction : {0.002, 0.01}) {
      Mesh out = in;
      const Options o = bounded(fraction * diag);
      const Report r = simplify(out, o);
      ASSERT_EQ(vrs_test::check_run(in, out, o, r), "") << name;
      EXPECT_EQ(r.stop, StopReason::ErrorBound) << name;
      EXPECT_LE(r.error_bound, o.max_error) << name;
      EXPECT_GT(r.removed, in.vertex_count() / 4) << name << " at " << fraction;
      EXPECT_LE(farthest_removed(in, out, r), r.error_bound * (1 + 1e-6)) << name;
    }
  }
}

TEST(ErrorBound, WhicheverOfBoundAndFaceTargetComesFirst) {
  const std::string path = vrs_test::cgal_mesh("elephant.off");
  if (path.empty()) GTEST_SKIP() << "CGAL data set missing";
  const Mesh in = vrs_test::read_off(path);
  const double diag = bounding_box_diagonal(in);
  Mesh loose = in, tight = in;
  const Report a = simplify(loose, bounded(0.05 * diag, in.face_count() / 2));
  EXPECT_EQ(a.stop, StopReason::TargetReached);
  EXPECT_LE(loose.face_count(), in.face_count() / 2);
  const Report b = simplify(tight, bounded(0.0005 * diag, in.face_count() / 2));
  EXPECT_EQ(b.stop, StopReason::ErrorBound);
  EXPECT_GT(tight.face_count(), in.face_count() / 2);
  EXPECT_LE(b.error_bound, 0.0005 * diag);
}

TEST(ErrorBound, SameOutputOnAnyThreadCount) {
  const std::string path = vrs_test::cgal_mesh("fandisk.off");
  if (path.empty()) GTEST_SKIP() << "CGAL data set missing";
  const Mesh in = vrs_test::read_off(path);
  Options o = bounded(0.01 * bounding_box_diagonal(in));
  o.threads = 3;
  Mesh out = in;
  const Report r = simplify(out, o);
  EXPECT_EQ(vrs_test::check_rerun(in, o, out, r), "");
}

TEST(ErrorBound, BadBoundsAreRefused) {
  for (double bad : {-1.0, std::nan("")}) {
    Mesh m = vrs_test::hexagon_fan(0.1f);
    const Mesh before = m;
    const Report r = simplify(m, bounded(bad));
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.message.find("max error"), std::string::npos) << r.message;
    EXPECT_TRUE(vrs_test::same_bits(m, before));
  }
}

TEST(ErrorBound, NotTrackedReportsNone) {
  Mesh m = vrs_test::hexagon_fan(0.25f);
  const Report r = simplify(m, bounded(0.0));
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.removed, 1u);
  EXPECT_EQ(r.error_bound, 0.0);
}
