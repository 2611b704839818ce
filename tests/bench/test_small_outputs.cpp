// Small outputs (a few dozen to a few hundred faces), judged by the benchmark's own fold-over
// measure: a new triangle of a thousandth of the input's area or more is asked against the
// input whatever its corners say, so that no run leaves a percent of its area folded where
// MeshLab's QECD does not (issue 28).
#include <gtest/gtest.h>

#include <string>
#include <unistd.h>

#include "mesh_checks.h"
#include "mesh_io.h"
#include "surface_error.h"
#include "test_meshes.h"

namespace {

// Read as the benchmark reads it (vcglib's importers, the file's order).
vrs::Mesh load(const std::string& path) {
  vrs_tool::LoadResult loaded = vrs_tool::load(path);
  if (!loaded.doc) return {};
  vrs::Mesh m = vrs_tool::to_core(*loaded.doc);
  vrs_tool::close(loaded.doc);
  return m;
}

vrs::Options at(double ratio) {
  vrs::Options o;
  o.target.kind = vrs::TargetKind::Ratio;
  o.target.ratio = ratio;
  o.split_vertices = vrs::SplitVertices::Weld; // positions only, as the benchmark and the CLI
  return o;
}

} // namespace

// CGAL's ALSTOM_TEST4 at 1 % (20 faces) folded 3.0 % of its area and assimp's Wuson at 10 %
// (372 faces) 1.3 %, their large triangles' corners agreeing with the input that their
// middles turned from (QECD: 0.47 and 0.92 %). Now 0.73 and 0.91 %.
TEST(SmallOutputs, LargeTrianglesDoNotFoldOverAPercentOfTheArea) {
  const std::string alstom = vrs_test::cgal_mesh("ALSTOM_TEST4.off");
  const std::string wuson = "/usr/share/assimp/models/OFF/Wuson.off";
  if (alstom.empty()) GTEST_SKIP() << "CGAL's data set is missing";
  if (access(wuson.c_str(), R_OK) != 0) GTEST_SKIP() << "assimp's test models are missing";
  for (const auto& [path, ratio] : {std::pair{alstom, 0.01}, std::pair{wuson, 0.1}}) {
    SCOPED_TRACE(path + " at " + std::to_string(ratio));
    const vrs::Mesh in = load(path);
    ASSERT_GT(in.face_count(), 2000u);
    vrs::Mesh out = in;
    const vrs::Options o = at(ratio);
    const vrs::Report r = vrs::simplify(out, o);
    ASSERT_TRUE(r.ok) << r.message;
    // The target reached (within a face: a closed mesh's count is even).
    EXPECT_LE(out.face_count(), size_t(ratio * double(in.face_count()) + 0.5) + 1) << r.stop_detail;
    EXPECT_EQ(vrs_test::check_run(in, out, o, r), "");
    EXPECT_LT(vrs_bench::fold_over_share(in, out, 30000), 0.01);
  }
}

// CGAL's boeing: panels written in different orientations (a staircase of tiers whose floors
// and walls disagree as written), welded for the run. A slope of a wall's orientation across
// the tiers agreed with both as the run held them; written back, it faced against the floors
// nearest it: at 10 %, 2.5 % of the output's area folded against QECD's 0.17 %. Judged as
// written, 1.1 %; with the small triangles where corners doubt asked of the input too (the
// corners' normals cannot see how a piece was written), 0.77 %.
TEST(SmallOutputs, PiecesWrittenInOtherOrientationsAreJudgedAsWritten) {
  const std::string boeing = vrs_test::cgal_mesh("boeing.off");
  if (boeing.empty()) GTEST_SKIP() << "CGAL's data set is missing";
  const vrs::Mesh in = load(boeing);
  vrs::Mesh out = in;
  const vrs::Options o = at(0.1);
  const vrs::Report r = vrs::simplify(out, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_GT(r.welded_vertices, 0u);
  EXPECT_EQ(r.reoriented_faces, 0u) << "every face written as its input was";
  EXPECT_EQ(vrs_test::check_run(in, out, o, r), "");
  EXPECT_LT(vrs_bench::fold_over_share(in, out, 30000), 0.01);
}
