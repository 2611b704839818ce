// Property tests on real meshes of CGAL's data set (Debian libcgal-demo): at 50 %, 10 % and 1 %
// with either priority the output keeps every invariant, and reaches the target or says why not.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "mesh_checks.h"
#include "test_meshes.h"

using namespace vrs;

class RealMesh : public ::testing::TestWithParam<std::tuple<const char*, double, Priority>> {};

TEST_P(RealMesh, KeepsTheInvariants) {
  const auto [name, ratio, priority] = GetParam();
  const std::string path = vrs_test::cgal_mesh(name);
  if (path.empty()) GTEST_FAIL() << name << " missing: run scripts/setup.sh (libcgal-demo data)";
  const Mesh in = vrs_test::read_off(path);
  ASSERT_GT(in.face_count(), 0u);
  Mesh m = in;
  Options o;
  o.target.ratio = ratio;
  o.priority = priority;
  const Report r = simplify(m, o);
  ASSERT_TRUE(r.ok) << r.message;

  EXPECT_EQ(vrs_test::check_indices(m), "");
  EXPECT_EQ(vrs_test::check_subset(in, m, r), "");
  EXPECT_EQ(vrs_test::check_boundary_kept(in, m, r), "");
  const auto before = vrs_test::edge_stats(in), after = vrs_test::edge_stats(m);
  EXPECT_LE(after.nonmanifold, before.nonmanifold);
  EXPECT_EQ(after.boundary, before.boundary); // boundary kept, so exactly the same edges
  EXPECT_EQ(after.euler(), before.euler());
  EXPECT_LE(vrs_test::count_degenerate(m), vrs_test::count_degenerate(in));
  EXPECT_EQ(vrs_test::count_duplicate_directed_edges(m), 0u);
  // Flipped against the original surface: the new face and its corners' input normals disagree.
  EXPECT_EQ(vrs_test::count_flipped(in, m, r), 0u);

  const size_t target = size_t(std::llround(ratio * double(in.face_count())));
  if (r.target_reached) {
    EXPECT_EQ(r.stop, StopReason::TargetReached);
    EXPECT_LE(m.face_count(), target);
  } else {
    EXPECT_EQ(r.stop, StopReason::NoCandidates);
    EXPECT_GT(m.face_count(), target);
  }
  if (ratio >= 0.1) {
    EXPECT_TRUE(r.target_reached) << m.face_count() << " faces for " << target;
  }
  RecordProperty("faces", int(m.face_count()));
}

INSTANTIATE_TEST_SUITE_P(
    CgalData, RealMesh,
    ::testing::Combine(::testing::Values("bunny00.off", "armadillo.off", "fandisk.off",
                                         "elephant.off", "mushroom.off", "three_peaks.off"),
                       ::testing::Values(0.5, 0.1, 0.01),
                       ::testing::Values(Priority::Factor, Priority::LocalError)),
    [](const auto& info) {
      std::string n = std::get<0>(info.param);
      n = n.substr(0, n.find('.'));
      return n + "_" + std::to_string(int(std::get<1>(info.param) * 100)) + "pct_" +
             (std::get<2>(info.param) == Priority::Factor ? "factor" : "local_error");
    });
