// Every kind of bad input gets a clear error (mesh untouched) or is handled with a valid result.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "mesh_checks.h"
#include "test_meshes.h"

using namespace vrs;

namespace {

Options ratio(double r) {
  Options o;
  o.target.ratio = r;
  return o;
}

void expect_valid(const Mesh& in, const Mesh& out, const Report& r) {
  ASSERT_EQ(vrs_test::check_valid(in, out, r), "");
}

void expect_refused(Mesh m, const Options& o, const std::string& words) {
  const Mesh before = m;
  Report r = simplify(m, o);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.stop, StopReason::InvalidInput);
  EXPECT_NE(r.message.find(words), std::string::npos) << r.message;
  EXPECT_EQ(m.positions, before.positions);
  EXPECT_EQ(m.triangles, before.triangles);
}

} // namespace

TEST(BadInput, OutOfRangeIndexIsRefusedWithTheFaceNamed) {
  Mesh m = vrs_test::icosphere(1);
  m.triangles[3 * 17 + 1] = 999;
  expect_refused(m, ratio(0.5), "triangle 17 has vertex index 999, out of range");
}

TEST(BadInput, RaggedArraysAreRefused) {
  Mesh m = vrs_test::icosphere(1);
  m.positions.pop_back();
  expect_refused(m, ratio(0.5), "positions size");
  m = vrs_test::icosphere(1);
  m.triangles.pop_back();
  expect_refused(m, ratio(0.5), "triangles size");
}

TEST(BadInput, BadOptionsAreRefused) {
  Mesh m = vrs_test::icosphere(1);
  expect_refused(m, ratio(-0.1), "ratio must be in [0, 1]");
  expect_refused(m, ratio(std::nan("")), "ratio must be in [0, 1]");
  Options o;
  o.tuning.intervals = 1;
  expect_refused(m, o, "intervals");
  o = Options();
  o.max_valence = 1000;
  expect_refused(m, o, "max valence");
  o = Options();
  o.max_normal_angle_deg = 0;
  expect_refused(m, o, "max normal angle");
  o = Options();
  o.target.kind = TargetKind::MaxFactor;
  o.target.max_factor = -1;
  expect_refused(m, o, "max factor");
  o = Options();
  std::vector<uint8_t> lock(3, 1);
  o.locked = &lock;
  expect_refused(m, o, "lock array has 3 entries");
  o = Options();
  o.mode = static_cast<Mode>(77);
  expect_refused(m, o, "unknown mode");
}

TEST(BadInput, AMeshWithoutFacesIsRefused) {
  Mesh m;
  expect_refused(m, ratio(0.5), "the mesh has no faces");
  Mesh points; // a point cloud: nothing to simplify, and no "target reached" either
  points.positions = {1, 2, 3, 4, 5, 6};
  expect_refused(points, ratio(0.5), "the mesh has no faces");
}

TEST(BadInput, NonFiniteCoordinatesAreKeptWithTheirNeighbours) {
  const float bad[] = {std::numeric_limits<float>::quiet_NaN(),
                       std::numeric_limits<float>::infinity(),
                       -std::numeric_limits<float>::infinity()};
  for (float value : bad) {
    Mesh in = vrs_test::icosphere(3);
    in.positions[3 * 100 + 1] = value;
    Mesh m = in;
    Report r = simplify(m, ratio(0.1));
    expect_valid(in, m, r);
    EXPECT_EQ(r.nonfinite_vertices, 1u);
    EXPECT_NE(r.remap[100], kRemoved);
    EXPECT_NE(r.message.find("NaN/inf"), std::string::npos);
    EXPECT_EQ(vrs_test::edge_stats(m).euler(), 2);
    EXPECT_LE(m.face_count(), size_t(0.1 * in.face_count()) + 2);
  }
}

TEST(BadInput, HugeCoordinatesDoNotOverflow) {
  Mesh in = vrs_test::icosphere(3);
  for (float& p : in.positions)
    p *= 3e37f;
  Mesh m = in;
  Report r = simplify(m, ratio(0.1));
  expect_valid(in, m, r);
  EXPECT_TRUE(r.target_reached);
  EXPECT_EQ(vrs_test::count_flipped(in, m, r), 0u);
}

TEST(BadInput, FacesWithARepeatedVertexAreDroppedAndReported) {
  Mesh in = vrs_test::icosphere(2);
  in.triangles.insert(in.triangles.end(), {5, 5, 6, 7, 8, 7});
  Mesh m = in;
  Report r = simplify(m, ratio(1.0));
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.dropped_degenerate_faces, 2u);
  EXPECT_EQ(m.face_count(), in.face_count() - 2);
  EXPECT_NE(r.message.find("repeated vertex"), std::string::npos);
}

TEST(BadInput, ZeroAreaTrianglesDoNotBreakTheRun) {
  Mesh in = vrs_test::grid(10);
  // Collapse a row of interior vertices onto their left neighbours' line: slivers of no area.
  for (int x = 1; x < 10; ++x)
    in.positions[3 * (5 * 11 + x) + 1] = 4.0f;
  Mesh m = in;
  Report r = simplify(m, ratio(0.2));
  expect_valid(in, m, r);
  EXPECT_LE(vrs_test::count_degenerate(m), vrs_test::count_degenerate(in));
}

TEST(BadInput, DuplicateTrianglesKeepTheirVertices) {
  Mesh in = vrs_test::icosphere(2);
  in.triangles.insert(in.triangles.end(), in.triangles.begin(), in.triangles.begin() + 3);
  Mesh m = in;
  Report r = simplify(m, ratio(0.1));
  expect_valid(in, m, r);
  for (int c = 0; c < 3; ++c)
    EXPECT_NE(r.remap[in.triangles[c]], kRemoved);
  EXPECT_GT(r.kept_nonmanifold, 0u);
}

TEST(BadInput, NonManifoldEdgeVerticesAreKept) {
  Mesh in = vrs_test::icosphere(2);
  // A fin: one extra face on the edge (a, b) of the first face, towards a new vertex.
  const uint32_t a = in.triangles[0], b = in.triangles[1];
  in.positions.insert(in.positions.end(), {0, 3, 0});
  uint32_t fin = uint32_t(in.vertex_count() - 1);
  in.triangles.insert(in.triangles.end(), {a, b, fin});
  ASSERT_EQ(vrs_test::edge_stats(in).nonmanifold, 1u);
  Mesh m = in;
  Report r = simplify(m, ratio(0.1));
  expect_valid(in, m, r);
  EXPECT_NE(r.remap[a], kRemoved);
  EXPECT_NE(r.remap[b], kRemoved);
  EXPECT_EQ(vrs_test::edge_stats(m).nonmanifold, 1u);
}

TEST(BadInput, HugeValenceHubsAreKeptAndTheRestSimplifies) {
  // Double cone: two hubs of valence 3000 around a ring of 3000 vertices.
  const int n = 3000;
  Mesh in;
  for (int i = 0; i < n; ++i) {
    float a = 2 * 3.14159265f * float(i) / float(n);
    in.positions.insert(in.positions.end(), {std::cos(a), std::sin(a), 0.01f * std::sin(7 * a)});
  }
  in.positions.insert(in.positions.end(), {0, 0, 1, 0, 0, -1});
  for (uint32_t i = 0; i < uint32_t(n); ++i) {
    uint32_t j = (i + 1) % n;
    in.triangles.insert(in.triangles.end(), {uint32_t(n), i, j, uint32_t(n + 1), j, i});
  }
  Mesh m = in;
  Report r = simplify(m, ratio(0.1));
  expect_valid(in, m, r);
  EXPECT_EQ(r.kept_high_valence, 2u);
  EXPECT_NE(r.remap[n], kRemoved);
  EXPECT_NE(r.remap[n + 1], kRemoved);
  EXPECT_GT(r.removed, size_t(n / 2));
  EXPECT_EQ(vrs_test::edge_stats(m).euler(), 2);
}

TEST(BadInput, IsolatedVerticesAreLeftInPlace) {
  Mesh in = vrs_test::icosphere(2);
  in.positions.insert(in.positions.end(), {9, 9, 9, 8, 8, 8});
  Mesh m = in;
  Report r = simplify(m, ratio(0.2));
  expect_valid(in, m, r);
  EXPECT_EQ(r.unreferenced_vertices, 2u);
  EXPECT_NE(r.remap[in.vertex_count() - 1], kRemoved);
  EXPECT_NE(r.remap[in.vertex_count() - 2], kRemoved);
}

TEST(BadInput, RandomTriangleSoupsGiveValidResults) {
  // Arbitrary soups: repeated, flipped, non-manifold and degenerate faces, a few non-finite
  // coordinates, every target kind and mode. Each result must be a valid subset mesh.
  std::mt19937 rng(2026);
  for (int trial = 0; trial < 300; ++trial) {
    Mesh in;
    const uint32_t nv = 4 + rng() % 60;
    for (uint32_t v = 0; v < 3 * nv; ++v)
      in.positions.push_back(float(rng() % 17) - 8.0f);
    if (trial % 7 == 0) in.positions[rng() % in.positions.size()] = NAN;
    const uint32_t nf = rng() % 150;
    for (uint32_t f = 0; f < 3 * nf; ++f)
      in.triangles.push_back(rng() % nv);
    Options o;
    o.target.kind = static_cast<TargetKind>(trial % 5);
    o.target.faces = rng() % 100;
    o.target.vertices = rng() % 40;
    o.target.ratio = double(rng() % 101) / 100;
    o.target.max_factor = double(rng() % 5);
    o.mode = static_cast<Mode>(trial % 3);
    o.tuning.queue = trial % 2 ? QueueKind::Heap : QueueKind::Intervals;
    o.simplify_boundary = trial % 4 == 0;
    o.tuning.intervals = 2 + int(rng() % 50);
    Mesh m = in;
    Report r = simplify(m, o);
    if (nf == 0) { // nothing to simplify: refused, the mesh as it was
      ASSERT_FALSE(r.ok) << "trial " << trial;
      ASSERT_EQ(m.positions, in.positions) << "trial " << trial;
      continue;
    }
    ASSERT_EQ(vrs_test::check_valid(in, m, r), "") << "trial " << trial;
  }
}
