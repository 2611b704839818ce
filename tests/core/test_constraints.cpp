// Constrained edges (seams, material borders, creases): which vertices they keep, removal along
// them, and the per-corner data (Report::corner_source) of every new face.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "mesh_checks.h"
#include "test_meshes.h"
#include "vrs/simplify.h"

namespace {

using vrs_test::check_run;

// Texture coordinates per input corner: (x, y) of the corner's vertex, shifted by 10 * chart,
// so a corner's value tells both its vertex and its chart.
struct Wedges {
  std::vector<float> uv; // 2 per input corner
};

Wedges wedges_by_chart(const vrs::Mesh& m, const std::vector<int>& chart_of_face) {
  Wedges w;
  for (size_t c = 0; c < m.triangles.size(); ++c) {
    uint32_t v = m.triangles[c];
    float shift = 10.0f * float(chart_of_face[c / 3]);
    w.uv.push_back(m.positions[3 * v] + shift);
    w.uv.push_back(m.positions[3 * v + 1]);
  }
  return w;
}

// Edges between faces of different charts: the seams an adapter derives from wedge data.
std::vector<uint32_t> seams_between(const vrs::Mesh& m, const std::vector<int>& chart_of_face) {
  std::map<std::pair<uint32_t, uint32_t>, std::vector<int>> charts;
  for (size_t f = 0; f < m.face_count(); ++f)
    for (int c = 0; c < 3; ++c) {
      uint32_t a = m.triangles[3 * f + c], b = m.triangles[3 * f + (c + 1) % 3];
      charts[{std::min(a, b), std::max(a, b)}].push_back(chart_of_face[f]);
    }
  std::vector<uint32_t> e;
  for (const auto& [edge, cs] : charts)
    if (std::any_of(cs.begin(), cs.end(), [&](int c) { return c != cs[0]; }))
      e.insert(e.end(), {edge.first, edge.second});
  return e;
}

// Each output corner's wedge (taken through corner_source) must be its own vertex's value in
// the chart of the face; the three corners of a face in one chart. Returns the faces checked.
size_t check_wedges(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r,
                    const Wedges& w) {
  std::vector<uint32_t> original(out.vertex_count());
  for (size_t v = 0; v < r.remap.size(); ++v)
    if (r.remap[v] != vrs::kRemoved) original[r.remap[v]] = uint32_t(v);
  EXPECT_EQ(r.corner_source.size(), out.triangles.size());
  for (size_t f = 0; f < out.face_count(); ++f) {
    float first_chart = -1;
    for (int c = 0; c < 3; ++c) {
      uint32_t s = r.corner_source[3 * f + c], v = original[out.triangles[3 * f + c]];
      // The chart whose shift comes nearest, then the value exactly as wedges_by_chart made it
      // (a jittered x minus its shifted self is not exact).
      const float chart = std::round((w.uv[2 * s] - in.positions[3 * v]) / 10.0f);
      EXPECT_EQ(w.uv[2 * s], in.positions[3 * v] + 10.0f * chart)
          << "face " << f << ": another vertex's value";
      EXPECT_EQ(w.uv[2 * s + 1], in.positions[3 * v + 1]) << "face " << f;
      if (c == 0) first_chart = chart;
      EXPECT_EQ(chart, first_chart) << "face " << f << " spans two charts";
    }
  }
  return out.face_count();
}

// faces == 0: every vertex whose removal costs nothing goes (a priority bound, not a count, so
// the last-resort pass does not run). On these flat unit grids the flat and straight removals
// cost 0 and cutting an outline corner off at least 0.7 (its distance to the new edge): 0.5
// keeps the corners.
vrs::Options with(const std::vector<uint32_t>* edges, size_t faces) {
  vrs::Options o;
  o.constrained_edges = edges;
  o.corner_sources = true;
  o.target.kind = faces ? vrs::TargetKind::Faces : vrs::TargetKind::MaxFactor;
  o.target.faces = faces;
  o.target.max_factor = 0.5;
  return o;
}

// Chart of each face from its centroid's (x, y).
template <class ChartOf> std::vector<int> charts_by_centroid(const vrs::Mesh& m, ChartOf chart_of) {
  std::vector<int> chart;
  for (size_t f = 0; f < m.face_count(); ++f) {
    float x = 0, y = 0;
    for (int c = 0; c < 3; ++c) {
      x += m.positions[3 * m.triangles[3 * f + c]] / 3;
      y += m.positions[3 * m.triangles[3 * f + c] + 1] / 3;
    }
    chart.push_back(chart_of(x, y));
  }
  return chart;
}

TEST(Constraints, FanInsideOneChartCarriesItsCornersExactly) {
  vrs::Mesh in = vrs_test::hexagon_fan(), out = in;
  std::vector<int> chart(in.face_count(), 0);
  Wedges w = wedges_by_chart(in, chart);
  vrs::Options o = with(nullptr, 4);
  vrs::Report r = vrs::simplify(out, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(out.face_count(), 4u);
  EXPECT_EQ(r.remap[6], vrs::kRemoved); // the centre went
  EXPECT_EQ(check_wedges(in, out, r, w), 4u);
  EXPECT_EQ(check_run(in, out, o, r), "");
}

TEST(Constraints, StraightSeamVertexGoesAlongTheSeamAndEachSideKeepsItsWedges) {
  vrs::Mesh in = vrs_test::grid(8), out = in;
  // The seam is the column x = 4.
  std::vector<int> chart = charts_by_centroid(in, [](float x, float) { return x < 4 ? 0 : 1; });
  std::vector<uint32_t> seams = seams_between(in, chart);
  ASSERT_EQ(seams.size(), 2u * 8);
  Wedges w = wedges_by_chart(in, chart);
  vrs::Options o = with(&seams, 0);
  o.simplify_boundary = true;
  vrs::Report r = vrs::simplify(out, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.constrained_edges, 8u);
  // The seam's inner vertices go along it, its ends (on the border) stay; each side is a flat
  // rectangle whose border may go too, down to 2 triangles a side.
  size_t seam_kept = 0;
  for (int y = 0; y <= 8; ++y)
    seam_kept += r.remap[uint32_t(y * 9 + 4)] != vrs::kRemoved;
  EXPECT_EQ(seam_kept, 2u);
  EXPECT_EQ(out.face_count(), 4u);
  check_wedges(in, out, r, w);
  EXPECT_EQ(check_run(in, out, o, r), "");
}

// A caller that runs the output again (a tiled run's next level) is told which output sides are
// constrained: values alone may not tell a seam whose two charts agree at both its ends.
TEST(Constraints, TheOutputSaysWhichOfItsSidesAreConstrained) {
  vrs::Mesh in = vrs_test::grid(8), out = in;
  std::vector<int> chart = charts_by_centroid(in, [](float x, float) { return x < 4 ? 0 : 1; });
  std::vector<uint32_t> seams = seams_between(in, chart);
  vrs::Options o = with(&seams, 0);
  o.corner_sources = true;
  o.target.kind = vrs::TargetKind::Faces;
  o.target.faces = 40;
  vrs::Report r = vrs::simplify(out, o);
  ASSERT_TRUE(r.ok) << r.message;
  ASSERT_EQ(r.constrained_sides.size(), out.face_count());
  std::vector<float> x_of(out.vertex_count());
  for (size_t v = 0; v < r.remap.size(); ++v)
    if (r.remap[v] != vrs::kRemoved) x_of[r.remap[v]] = in.positions[3 * v];
  size_t flagged = 0;
  for (size_t f = 0; f < out.face_count(); ++f)
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = out.triangles[3 * f + c], b = out.triangles[3 * f + (c + 1) % 3];
      const bool on_seam = x_of[a] == 4.0f && x_of[b] == 4.0f; // the column x = 4
      EXPECT_EQ(bool(r.constrained_sides[f] >> c & 1), on_seam) << "face " << f << " side " << c;
      flagged += on_seam;
    }
  EXPECT_GT(flagged, 0u);
  o.corner_sources = false; // not asked: none
  out = in;
  EXPECT_TRUE(vrs::simplify(out, o).constrained_sides.empty());
}

TEST(Constraints, SeamCornerWithThreeSeamEdgesIsKept) {
  // Charts: x < 4 is chart 0; x > 4 is split at y = 4 into charts 1 and 2. Vertex (4, 4) has
  // three seam edges (up, down, right).
  vrs::Mesh in = vrs_test::grid(8), out = in;
  std::vector<int> chart = charts_by_centroid(in, [](float x, float y) {
    return x < 4 ? 0 : y < 4 ? 1 : 2;
  });
  std::vector<uint32_t> seams = seams_between(in, chart);
  Wedges w = wedges_by_chart(in, chart);
  vrs::Options o = with(&seams, 0);
  vrs::Report r = vrs::simplify(out, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_NE(r.remap[4 * 9 + 4], vrs::kRemoved);
  EXPECT_GE(r.kept_constrained, 1u);
  check_wedges(in, out, r, w);
  EXPECT_EQ(check_run(in, out, o, r), "");
}

TEST(Constraints, CrossingSeamsKeepTheCrossing) {
  const vrs::Mesh in = vrs_test::grid(8, 0.1f);
  std::vector<int> chart =
      charts_by_centroid(in, [](float x, float y) { return (x < 4 ? 0 : 1) + (y < 4 ? 0 : 2); });
  std::vector<uint32_t> seams = seams_between(in, chart);
  Wedges w = wedges_by_chart(in, chart);
  for (bool lazy : {true, false}) {
    vrs::Mesh out = in;
    vrs::Options o = with(&seams, 0);
    o.simplify_boundary = true;
    o.tuning.lazy_from_faces =
        lazy ? 0 : o.tuning.lazy_from_faces; // eager: the default on a small mesh
    vrs::Report r = vrs::simplify(out, o);
    ASSERT_TRUE(r.ok) << r.message;
    EXPECT_NE(r.remap[4 * 9 + 4], vrs::kRemoved); // four seam edges meet there
    check_wedges(in, out, r, w);
    EXPECT_EQ(check_run(in, out, o, r), "");
    // Four flat quadrants, each down to its four corners: two triangles. Priced at once, the
    // last inner vertex of one seam is priced after its fan grew to a quadrant: 0.58, past
    // the bound of 0.5, so it stays (two faces more).
    EXPECT_EQ(out.face_count(), lazy ? 4u * 2 : 4u * 2 + 2) << (lazy ? "lazy" : "eager");
  }
}

TEST(Constraints, BentSeamFollowsItsPolylineWithinItsPriority) {
  // A seam that zig-zags by one column along a flat grid: removal along it straightens it, so
  // its vertices go only as their distance to the chord allows (max factor 0.1 keeps the bends).
  vrs::Mesh in = vrs_test::grid(8), out = in;
  std::vector<int> chart =
      charts_by_centroid(in, [](float x, float y) { return x < 4 + (int(y) % 2) ? 0 : 1; });
  std::vector<uint32_t> seams = seams_between(in, chart);
  Wedges w = wedges_by_chart(in, chart);
  vrs::Options o = with(&seams, 0);
  o.target.kind = vrs::TargetKind::MaxFactor;
  o.target.max_factor = 0.1;
  vrs::Report r = vrs::simplify(out, o);
  ASSERT_TRUE(r.ok) << r.message;
  // Every vertex where the seam turns stays.
  std::set<uint32_t> seam_vertices(seams.begin(), seams.end());
  for (uint32_t v : seam_vertices) {
    int x = int(v % 9), y = int(v / 9);
    if (y > 0 && y < 8 && (x == 4 || x == 5)) {
      bool turns = true; // on this zig-zag every inner seam vertex is a turn
      EXPECT_TRUE(!turns || r.remap[v] != vrs::kRemoved) << "seam vertex " << x << "," << y;
    }
  }
  check_wedges(in, out, r, w);
  EXPECT_EQ(check_run(in, out, o, r), "");
  EXPECT_LT(out.face_count(), in.face_count()); // the flat parts still went
}

TEST(Constraints, FeatureAngleKeepsACreaseStraight) {
  // A sheet folded at x = 4 (90 degrees): without the option the crease may be cut across;
  // with a 45 degree feature angle no face spans both planes.
  vrs::Mesh in = vrs_test::grid(8);
  for (size_t i = 0; i < in.positions.size(); i += 3)
    if (in.positions[i] > 4) {
      in.positions[i + 2] = in.positions[i] - 4;
      in.positions[i] = 4;
    }
  vrs::Mesh out = in;
  vrs::Options o;
  o.feature_angle_deg = 45;
  o.simplify_boundary = true;
  o.target.kind = vrs::TargetKind::MaxFactor; // what costs nothing, without the last resort
  o.target.max_factor = 0.5;                  // (the outline's corners stay, as in with())
  vrs::Report r = vrs::simplify(out, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.constrained_edges, 8u);
  for (size_t f = 0; f < out.face_count(); ++f) {
    bool off_x = false, off_z = false;
    for (int c = 0; c < 3; ++c) {
      const float* p = &out.positions[3 * out.triangles[3 * f + c]];
      off_x |= p[0] < 4; // in the z = 0 plane, left of the crease
      off_z |= p[2] > 0; // in the x = 4 plane
    }
    EXPECT_FALSE(off_x && off_z) << "face " << f << " spans the crease";
  }
  EXPECT_EQ(out.face_count(), 4u);
  EXPECT_EQ(check_run(in, out, o, r), "");
}

TEST(Constraints, BadConstraintsAreRefused) {
  vrs::Mesh in = vrs_test::grid(3), out = in;
  std::vector<uint32_t> odd{0, 1, 2};
  vrs::Options o = with(&odd, 2);
  vrs::Report r = vrs::simplify(out, o);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("pairs"), std::string::npos) << r.message;
  std::vector<uint32_t> far{0, 99};
  o.constrained_edges = &far;
  r = vrs::simplify(out, o);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("out of range"), std::string::npos) << r.message;
  o.constrained_edges = nullptr;
  o.feature_angle_deg = 200;
  r = vrs::simplify(out, o);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(vrs_test::same_bits(out, in));
}

TEST(Constraints, PairsThatAreNotEdgesAreIgnored) {
  vrs::Mesh in = vrs_test::hexagon_fan(), out = in;
  std::vector<uint32_t> not_edges{0, 3}; // opposite ring vertices
  vrs::Options o = with(&not_edges, 4);
  vrs::Report r = vrs::simplify(out, o);
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.constrained_edges, 0u);
  EXPECT_EQ(out.face_count(), 4u);
}

// Random charts on real meshes: faces grouped by which side of a few random planes their
// centroid lies; the seams between them constrained.
class RandomCharts : public ::testing::TestWithParam<std::tuple<const char*, double>> {};

TEST_P(RandomCharts, EveryFaceTakesItsCornersFromOneChart) {
  auto [name, ratio] = GetParam();
  std::string path = vrs_test::cgal_mesh(name);
  if (path.empty()) GTEST_FAIL() << name << " missing: run scripts/setup.sh (libcgal-demo data)";
  vrs::Mesh in = vrs_test::read_off(path), out = in;
  std::mt19937 rng(7);
  std::normal_distribution<float> g;
  float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
  for (size_t i = 0; i < in.positions.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], in.positions[i]);
    hi[i % 3] = std::max(hi[i % 3], in.positions[i]);
  }
  std::vector<std::array<float, 4>> planes;
  for (int p = 0; p < 3; ++p) {
    std::array<float, 4> pl{g(rng), g(rng), g(rng), 0};
    for (int k = 0; k < 3; ++k)
      pl[3] -= pl[k] * (lo[k] + (hi[k] - lo[k]) * (0.3f + 0.4f * float(p) / 2));
    planes.push_back(pl);
  }
  std::vector<int> chart;
  for (size_t f = 0; f < in.face_count(); ++f) {
    float c[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d)
        c[d] += in.positions[3 * in.triangles[3 * f + k] + d] / 3;
    int id = 0;
    for (size_t p = 0; p < planes.size(); ++p)
      id |= (planes[p][0] * c[0] + planes[p][1] * c[1] + planes[p][2] * c[2] + planes[p][3] > 0)
            << p;
    chart.push_back(id);
  }
  std::vector<uint32_t> seams = seams_between(in, chart);
  ASSERT_GT(seams.size(), 0u);
  Wedges w = wedges_by_chart(in, chart);
  vrs::Options o = with(&seams, size_t(std::llround(double(in.face_count()) * ratio)));
  vrs::Report r = vrs::simplify(out, o);
  ASSERT_TRUE(r.ok) << r.message;
  check_wedges(in, out, r, w);
  EXPECT_EQ(check_run(in, out, o, r), "");
  EXPECT_LT(out.face_count(), in.face_count());
}

INSTANTIATE_TEST_SUITE_P(CgalMeshes, RandomCharts,
                         ::testing::Combine(::testing::Values("bunny00.off", "fandisk.off",
                                                              "elephant.off", "mushroom.off"),
                                            ::testing::Values(0.5, 0.1, 0.01)));

} // namespace
