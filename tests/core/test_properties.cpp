// Property tests on real meshes of CGAL's data set (Debian libcgal-demo): at 50 %, 10 % and 1 %
// with either priority the output keeps every invariant, and reaches the target or says why not.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <tuple>

#include "fold_over.h"
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
  o.tuning.priority = priority;
  const Report r = simplify(m, o);
  ASSERT_TRUE(r.ok) << r.message;

  EXPECT_EQ(vrs_test::check_indices(m), "");
  EXPECT_EQ(vrs_test::check_subset(in, m, r), "");
  const auto before = vrs_test::edge_stats(in), after = vrs_test::edge_stats(m);
  EXPECT_LE(after.nonmanifold, before.nonmanifold);
  if (!r.boundary_simplified) { // kept unless it alone needed a quarter of the target
    EXPECT_EQ(vrs_test::check_boundary_kept(in, m, r), "");
    EXPECT_EQ(after.boundary, before.boundary); // boundary kept, so exactly the same edges
  }
  EXPECT_EQ(after.euler(), before.euler());
  EXPECT_LE(vrs_test::count_degenerate(m), vrs_test::count_degenerate(in));
  EXPECT_EQ(vrs_test::count_duplicate_directed_edges(m), 0u);
  // Flipped against the original surface: the new face and its corners' input normals disagree
  // (the promise while the input-normal veto holds: not after the last-resort pass).
  if (r.relaxed_removals == 0) {
    EXPECT_EQ(vrs_test::count_flipped(in, m, r), 0u);
  }
  // Turned over against every input face near it: never.
  EXPECT_EQ(vrs_test::count_fold_overs(in, m, r), 0u);

  const size_t target = size_t(std::llround(ratio * double(in.face_count())));
  if (r.target_reached) {
    EXPECT_EQ(r.stop, StopReason::TargetReached);
    EXPECT_LE(m.face_count(), target);
  } else {
    EXPECT_EQ(r.stop, StopReason::NoCandidates);
    EXPECT_GT(m.face_count(), target);
  }
  // 10 % is reached. At 1 %, a closed mesh reaches the target or stops where every filling
  // left would fold the surface over the input, or where the next removal would change the
  // surface abruptly (elephant: 160 faces for 56, a thin leg or trunk down to a prism; MeshLab's
  // QECD with Preserve Topology gets there by folding 14 % of the area over); an open one with
  // its boundary kept may stop short too, and then the report says the boundary is why, or
  // that every filling left would fold (mushroom at 1 %, a few faces over, since small
  // outputs' large faces are asked of the input).
  if (ratio >= 0.1) {
    EXPECT_TRUE(r.target_reached) << m.face_count() << " faces for " << target;
  } else if (before.boundary == 0) {
    if (double(m.face_count()) > std::max(1.05 * double(target), double(target + 8))) {
      EXPECT_TRUE(vrs_test::stops_faithfully(r)) << r.stop_detail;
    }
  } else if (!r.target_reached) {
    EXPECT_TRUE(r.stop_detail.find("boundary simplification is off") != std::string::npos ||
                vrs_test::stops_faithfully(r))
        << r.stop_detail;
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

// The fold-over check itself can fail: a new face turned over is caught, the same face the
// right way round is not.
TEST(FoldOverCheck, CatchesANewFaceTurnedOver) {
  const Mesh in = vrs_test::icosphere(3);
  Mesh m = in;
  Options o;
  o.target.ratio = 0.5;
  const Report r = simplify(m, o);
  ASSERT_TRUE(r.ok);
  ASSERT_EQ(vrs_test::count_fold_overs(in, m, r), 0u);
  size_t f = 0;
  while (f < r.face_source.size() && r.face_source[f] != kRemoved)
    ++f;
  ASSERT_LT(f, m.face_count()) << "no new face";
  std::swap(m.triangles[3 * f + 1], m.triangles[3 * f + 2]);
  EXPECT_EQ(vrs_test::count_fold_overs(in, m, r), 1u);
}

// What the fans are for: on elephant at 1 % the paper's projection alone runs out of removals
// far above the target (278 faces for 56); the best of projection and fans goes less than half
// as far from it, and stops where every filling left would fold the surface over the input or
// change it abruptly (160; with the input-normal veto lifted it reached 56 with 14 % of its
// area folded over).
TEST(Fill, BestReachesWhatTheProjectionAloneCannot) {
  const std::string path = vrs_test::cgal_mesh("elephant.off");
  if (path.empty()) GTEST_FAIL() << "elephant.off missing: run scripts/setup.sh";
  const Mesh in = vrs_test::read_off(path);
  const size_t target = size_t(std::llround(0.01 * double(in.face_count())));
  size_t faces[2];
  Report best;
  for (Fill fill : {Fill::Projection, Fill::Best}) {
    Mesh m = in;
    Options o;
    o.target.ratio = 0.01;
    o.tuning.fill = fill;
    const Report r = simplify(m, o);
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(vrs_test::check_run(in, m, o, r), "");
    faces[fill == Fill::Best] = m.face_count();
    best = r;
  }
  EXPECT_GT(double(faces[0]), 2.0 * double(target)) << "projection alone";
  EXPECT_LT(2 * (faces[1] - target), faces[0] - target) << "best";
  if (faces[1] > target + 2) {
    EXPECT_TRUE(vrs_test::stops_faithfully(best)) << best.stop_detail;
  }
}

// Closed meshes on which MeshLab's QECD with Preserve Topology reaches 1 % (and 10 % for the
// shuffled one), folding parts over to get there. Before the last resort's least-cost filling,
// elk stopped at 44 faces for 33 and femur at 104 for 78; with the fold-over judged against
// the input (not only the faces a removal replaces), elk, femur and spool stop short again
// where every filling left would fold or the surface would change abruptly (128, 304, 86
// faces since the relaxed passes answer to the input's nearest faces): faithfully, and saying
// so. The shuffled blobby, its faces in random orientation, gets there. Every invariant kept.
TEST(Targets, ClosedMeshesReachTheTargetOrStopWhereOnlyFoldsAreLeft) {
  for (auto [name, ratio] : {std::pair{"elk.off", 0.01},
                             {"femur.off", 0.01},
                             {"spool.off", 0.01},
                             {"blobby-shuffled.off", 0.1},
                             {"blobby-shuffled.off", 0.01}}) {
    const std::string path = vrs_test::cgal_mesh(name);
    if (path.empty()) GTEST_FAIL() << name << " missing: run scripts/setup.sh";
    const Mesh in = vrs_test::read_off(path);
    ASSERT_EQ(vrs_test::edge_stats(in).boundary, 0u) << name << " is closed";
    Mesh m = in;
    Options o;
    o.target.ratio = ratio;
    const Report r = simplify(m, o);
    const double target = std::llround(ratio * double(in.face_count()));
    // Reached, or stopped short where every filling left would fold over the input or change
    // the surface abruptly (never folded to get there: check_run below).
    if (double(m.face_count()) > std::max(1.05 * target, target + 2)) {
      EXPECT_TRUE(vrs_test::stops_faithfully(r))
          << name << " at " << ratio << ": " << r.stop_detail;
    }
    EXPECT_EQ(vrs_test::check_run(in, m, o, r), "") << name << " at " << ratio;
  }
}
