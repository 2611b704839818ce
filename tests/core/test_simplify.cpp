// Hand-built meshes with exact expected results, and the options of the entry point.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mesh_checks.h"
#include "test_meshes.h"

using namespace vrs;

namespace {

Options faces(size_t n) {
  Options o;
  o.target.kind = TargetKind::Faces;
  o.target.faces = n;
  return o;
}

double xy_area2(const Mesh& m) {
  double a = 0;
  for (size_t i = 0; i < m.triangles.size(); i += 3) {
    const float* p = &m.positions[3 * m.triangles[i]];
    const float* q = &m.positions[3 * m.triangles[i + 1]];
    const float* r = &m.positions[3 * m.triangles[i + 2]];
    double t = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    EXPECT_GT(t, 0) << "face " << i / 3 << " is not counter-clockwise in xy";
    a += t;
  }
  return a;
}

void expect_valid(const Mesh& in, const Mesh& out, const Report& r) {
  ASSERT_EQ(vrs_test::check_valid(in, out, r), "");
}

} // namespace

TEST(Simplify, FlatHexagonLosesItsCentreAndKeepsItsRim) {
  for (float h : {0.0f, 0.2f}) {
    Mesh in = vrs_test::hexagon_fan(h), m = in;
    Report r = simplify(m, faces(4));
    expect_valid(in, m, r);
    EXPECT_EQ(r.stop, StopReason::TargetReached);
    EXPECT_EQ(m.vertex_count(), 6u);
    EXPECT_EQ(m.face_count(), 4u);
    EXPECT_EQ(r.remap[6], kRemoved);
    EXPECT_NEAR(xy_area2(m), xy_area2(vrs_test::hexagon_fan()), 1e-5); // the hole is tiled
    EXPECT_EQ(vrs_test::check_boundary_kept(in, m, r), "");
  }
}

TEST(Simplify, ConcaveRingIsFilledByEarClipping) {
  Mesh in = vrs_test::concave_fan(), m = in;
  Report r = simplify(m, faces(0));
  expect_valid(in, m, r);
  ASSERT_EQ(m.face_count(), 4u);
  EXPECT_NEAR(xy_area2(m), xy_area2(in), 1e-5);
  // The notch (input vertex 3) is reflex: no new triangle may have it inside, i.e. no triangle
  // spans from vertex 2 to vertex 4 directly across it.
  for (size_t i = 0; i < m.triangles.size(); i += 3) {
    auto t = &m.triangles[i];
    bool has2 = std::count(t, t + 3, r.remap[2]), has4 = std::count(t, t + 3, r.remap[4]);
    bool has3 = std::count(t, t + 3, r.remap[3]);
    EXPECT_FALSE(has2 && has4 && !has3);
  }
}

TEST(Simplify, TetrahedronCannotLoseAVertex) {
  for (Priority p : {Priority::Factor, Priority::LocalError}) {
    Mesh in = vrs_test::tetrahedron(), m = in;
    Options o = faces(0);
    o.tuning.priority = p;
    Report r = simplify(m, o);
    expect_valid(in, m, r);
    EXPECT_EQ(m.face_count(), 4u);
    EXPECT_EQ(m.triangles, in.triangles);
    EXPECT_EQ(r.stop, StopReason::NoCandidates);
    EXPECT_FALSE(r.target_reached);
    // Each vertex refused once, once more when the input-normal veto is eased (one corner may
    // disagree) and once more by the last-resort pass (lifted) the unmet target starts.
    EXPECT_EQ(r.rejected_total(), 12u);
    EXPECT_EQ(r.relaxed_removals, 0u);
    // Each hole's only triangle is the opposite face. The local-error planning pass leaves
    // the mesh look-ups to the pop and sees first that the face would face inwards (in the
    // last-resort pass too: none of its corners' input normals agrees with it).
    const char* why = p == Priority::Factor ? "triangle_exists" : "flip";
    EXPECT_EQ(r.rejected[p == Priority::Factor ? RejectTriangle : RejectFlip], 12u);
    EXPECT_EQ(r.stop_detail,
              "remaining vertices: 4 refused by the vetoes (" + std::string(why) + " 4)");
    EXPECT_EQ(r.stop_cause, StopCause::Vetoes);
  }
}

TEST(Simplify, OpenSquareKeepsItsBoundary) {
  Mesh in = vrs_test::grid(8, 0.2f), m = in;
  Report r = simplify(m, faces(0));
  expect_valid(in, m, r);
  EXPECT_EQ(vrs_test::check_boundary_kept(in, m, r), "");
  EXPECT_EQ(r.kept_boundary, 32u);
  EXPECT_EQ(r.stop, StopReason::NoCandidates);
  EXPECT_NEAR(xy_area2(m), 2 * 64.0, 1e-3); // still covers the square, no fold
  EXPECT_EQ(m.face_count(), 30u);           // 32 boundary vertices, no interior left
}

// Boundary simplification: a straight border costs nothing; cutting an outline corner off
// costs its distance to the new edge (the local error), so a bound below that keeps the
// square, and a bound above it lets the corners go like anything else that cheap. The
// paper's factor cannot price the cut: with it the corners stay whatever the bound.
TEST(Simplify, BoundarySimplificationPricesTheOutlineCorners) {
  const Mesh in = vrs_test::grid(8);
  for (Priority priority : {Priority::LocalError, Priority::Factor})
    for (double bound : {0.5, 1e30}) {
      Mesh m = in;
      Options o; // a priority bound: no count to meet, so no last-resort pass
      o.target.kind = TargetKind::MaxFactor;
      o.target.max_factor = bound;
      o.tuning.priority = priority;
      o.simplify_boundary = true;
      Report r = simplify(m, o);
      expect_valid(in, m, r);
      EXPECT_EQ(vrs_test::edge_stats(m).euler(), vrs_test::edge_stats(in).euler());
      const bool square = priority == Priority::Factor || bound < 1;
      SCOPED_TRACE(square ? "square kept" : "corners priced");
      size_t corners_kept = 0;
      for (uint32_t corner : {0u, 8u, 72u, 80u})
        corners_kept += r.remap[corner] != kRemoved;
      if (square) {
        EXPECT_EQ(corners_kept, 4u);
        EXPECT_NEAR(xy_area2(m), 2 * 64.0, 1e-3);
        EXPECT_LT(m.vertex_count(), 8u); // straight edges: only corners (and a few blocked) stay
      } else {
        EXPECT_LT(corners_kept, 4u);
        EXPECT_LT(xy_area2(m), 2 * 64.0 - 1);
      }
    }
}

// A strip of hair from assimp's Wuson (four triangles, every border vertex a turn of 60-90°):
// on a real mesh fifty of them kept their corners until the last resort while the body was
// crushed to pay for them (Wuson at 10 %: 4.8x QECD's mean error). Priced, the strip thins
// in the ordinary passes.
TEST(Simplify, ASmallOpenPieceThinsBeforeAnyLastResort) {
  Mesh in;
  in.positions = {0.0213880f, 1.3214330f, 1.1891440f, 0.0003450f, 1.3309031f, 1.1889330f,
                  0.0283510f, 1.3317950f, 1.3225271f, 0.0003450f, 1.3411371f, 1.3252651f,
                  0.0430680f, 1.3057441f, 1.3252651f, 0.0320320f, 1.2971920f, 1.1886070f};
  in.triangles = {0, 1, 2, 3, 2, 1, 4, 5, 2, 0, 2, 5};
  for (Priority priority : {Priority::LocalError, Priority::Factor}) {
    Mesh m = in;
    Options o = faces(2);
    o.tuning.priority = priority;
    Report r = simplify(m, o);
    expect_valid(in, m, r);
    EXPECT_TRUE(r.boundary_simplified);
    EXPECT_EQ(m.face_count(), 2u);
    // The factor cannot price a corner: only its last resort thins the strip.
    if (priority == Priority::LocalError)
      EXPECT_EQ(r.relaxed_removals, 0u);
    else
      EXPECT_GT(r.relaxed_removals, 0u);
  }
}

// A count the allowed removals cannot meet starts the last resort: the factor's outline
// corners and single triangles may go, and the report counts those removals. The mesh stays
// valid.
TEST(Simplify, LastResortCutsOutlineCornersOnlyForACountTarget) {
  Mesh in = vrs_test::grid(8), m = in;
  Options o = faces(0);
  o.tuning.priority = Priority::Factor; // the local error prices the corners before any last resort
  o.simplify_boundary = true;
  o.max_price_jump = 0; // the target at any cost
  Report r = simplify(m, o);
  expect_valid(in, m, r);
  EXPECT_GT(r.relaxed_removals, 0u);
  EXPECT_LT(xy_area2(m), 2 * 64.0 - 1);
  EXPECT_EQ(vrs_test::edge_stats(m).euler(), vrs_test::edge_stats(in).euler());
  EXPECT_GE(m.face_count(), 1u); // the last triangle is never cut: that would empty the disc
}

// Cutting the outline's corners off costs far more than anything removed before it: with the
// default max_price_jump the run stops short instead, keeps the outline whole and says why.
TEST(Simplify, StopsShortRatherThanCutTheOutline) {
  const Mesh in = vrs_test::grid(8);
  for (bool lazy : {true, false}) {
    Mesh m = in;
    Options o = faces(0);
    o.simplify_boundary = true;
    o.tuning.lazy_from_faces =
        lazy ? 0 : o.tuning.lazy_from_faces; // eager: the default on a small mesh
    Report r = simplify(m, o);
    expect_valid(in, m, r);
    EXPECT_EQ(r.stop, StopReason::NoCandidates);
    EXPECT_NEAR(xy_area2(m), 2 * 64.0, 1e-3) << (lazy ? "lazy" : "eager");
    EXPECT_NE(r.stop_detail.find("stopped short of the target"), std::string::npos)
        << r.stop_detail;
    // The option named as users write it (Python's max_jump, the command line's --max-jump).
    EXPECT_NE(r.stop_detail.find("max_jump, --max-jump: 10"), std::string::npos) << r.stop_detail;
    // A flat grid's removals cost nothing: the jump is measured from the floor, and said so.
    EXPECT_NE(r.stop_detail.find("times a thousandth of the bounding box's diagonal"),
              std::string::npos)
        << r.stop_detail;
    EXPECT_EQ(r.stop_cause, StopCause::PriceJump);
    EXPECT_EQ(r.target_faces, 0u);
    // Lazy, the first jump comes with nothing cheap left; eager prices reach it with three
    // straight outline vertices still to take once eased (the outline stays whole: the area).
    EXPECT_EQ(r.relaxed_removals, lazy ? 0u : 3u);
  }
}

// A border that alone needs more than a quarter of the faces asked for is simplified too (and
// the report says so); with simplify_boundary_when_needed off it stays, as the paper has it.
TEST(Simplify, KeptBorderThatWouldTakeTheTargetIsSimplifiedToo) {
  const Mesh in = vrs_test::grid(16, 0.2f); // 512 faces, 64 border vertices: at least 62 faces
  for (bool when_needed : {true, false}) {
    Mesh m = in;
    Options o = faces(100);
    o.simplify_boundary_when_needed = when_needed;
    Report r = simplify(m, o);
    expect_valid(in, m, r);
    EXPECT_EQ(r.boundary_simplified, when_needed);
    EXPECT_EQ(vrs_test::check_boundary_kept(in, m, r) == "", !when_needed);
    EXPECT_EQ(vrs_test::check_run(in, m, o, r), "");
    if (when_needed) {
      EXPECT_LE(m.face_count(), 100u);
    }
  }
  // A target the kept border takes less than a quarter of leaves it alone.
  Mesh m = in;
  Report r = simplify(m, faces(300));
  EXPECT_FALSE(r.boundary_simplified);
  EXPECT_EQ(vrs_test::check_boundary_kept(in, m, r), "");
}

// A seam written as split vertices (two halves of a grid that share a column of positions but
// not its vertices), left apart (SplitVertices::Keep): when the border rule simplifies the
// border, that column stays on both sides, so the halves still meet without a crack; the outer
// border is simplified. (By default the column is welded: test_split_vertices, and below.)
TEST(Simplify, SplitSeamStaysWhenTheBorderIsSimplified) {
  const int n = 16;
  Mesh in;
  // Left half columns 0..8, right half columns 8..16 with column 8 written twice.
  auto add_half = [&](int x0) {
    const uint32_t base = uint32_t(in.vertex_count());
    for (int y = 0; y <= n; ++y)
      for (int x = x0; x <= x0 + n / 2; ++x)
        in.positions.insert(in.positions.end(),
                            {float(x), float(y), 0.3f * std::sin(0.7f * float(x * y))});
    const uint32_t w = n / 2 + 1;
    for (uint32_t y = 0; y < uint32_t(n); ++y)
      for (uint32_t x = 0; x + 1 < w; ++x) {
        const uint32_t a = base + y * w + x;
        in.triangles.insert(in.triangles.end(), {a, a + 1, a + w + 1, a, a + w + 1, a + w});
      }
  };
  add_half(0);
  add_half(n / 2);
  Mesh m = in;
  Options keep = faces(60);
  keep.split_vertices = SplitVertices::Keep;
  Report r = simplify(m, keep);
  expect_valid(in, m, r);
  ASSERT_TRUE(r.boundary_simplified);
  const uint32_t w = n / 2 + 1, half = uint32_t(in.vertex_count() / 2);
  size_t outer_removed = 0;
  for (uint32_t y = 0; y <= uint32_t(n); ++y) {
    EXPECT_NE(r.remap[y * w + w - 1], kRemoved) << "left side of the seam, row " << y;
    EXPECT_NE(r.remap[half + y * w], kRemoved) << "right side of the seam, row " << y;
    outer_removed += r.remap[y * w] == kRemoved;
  }
  EXPECT_GT(outer_removed, 0u); // the outer border was simplified
  // By default the column is welded for the run: it is simplified along itself, the same rows
  // going on both sides (no crack), and the target is reached with fewer faces to spare.
  Mesh welded = in;
  const Report rw = simplify(welded, faces(60));
  expect_valid(in, welded, rw);
  EXPECT_EQ(rw.welded_vertices, size_t(n + 1));
  EXPECT_TRUE(rw.target_reached) << rw.stop_detail;
  size_t seam_removed = 0;
  for (uint32_t y = 0; y <= uint32_t(n); ++y) {
    EXPECT_EQ(rw.remap[y * w + w - 1] == kRemoved, rw.remap[half + y * w] == kRemoved)
        << "row " << y << " went on one side of the seam only";
    seam_removed += rw.remap[half + y * w] == kRemoved;
  }
  EXPECT_GT(seam_removed, 0u);
}

TEST(Simplify, EveryTargetKindIsMetAndNotOvershot) {
  const Mesh in = vrs_test::icosphere(3); // 1280 faces, 642 vertices
  for (TargetKind kind : {TargetKind::Faces, TargetKind::Vertices, TargetKind::Ratio}) {
    Mesh m = in;
    Options o;
    o.target.kind = kind;
    o.target.faces = 300;
    o.target.vertices = 100;
    o.target.ratio = 0.25;
    Report r = simplify(m, o);
    expect_valid(in, m, r);
    EXPECT_TRUE(r.target_reached);
    EXPECT_EQ(r.stop, StopReason::TargetReached);
    // Closed mesh: each removal takes 2 faces and 1 vertex, and it stops as soon as it can.
    const size_t expect_faces = kind == TargetKind::Faces   ? 300
                                : kind == TargetKind::Ratio ? 320
                                                            : 196;
    EXPECT_EQ(m.face_count(), expect_faces); // 1280 - 2k lands on each target exactly
    EXPECT_EQ(m.vertex_count(), expect_faces / 2 + 2);
  }
}

TEST(Simplify, MaxFactorRemovesOnlyVerticesUnderIt) {
  // The threshold applies to whichever priority the table sorts by.
  for (Priority p : {Priority::Factor, Priority::LocalError}) {
    const Mesh in = vrs_test::icosphere(3);
    Mesh m = in;
    Options o;
    o.tuning.priority = p;
    o.target.kind = TargetKind::MaxFactor;
    // A sphere's vertices all stand ~0.01 off their neighbours' plane; a removal's patch, a
    // ring wide, sags further (and the local error weighs the patch's area).
    const double limit = p == Priority::Factor ? 0.01 : 0.05;
    o.target.max_factor = limit;
    Report r = simplify(m, o);
    expect_valid(in, m, r);
    EXPECT_EQ(r.stop, StopReason::MaxFactor);
    EXPECT_GT(r.removed, 0u);
    EXPECT_LT(r.removed, in.vertex_count() - 12); // the limit stops it well before the end
    EXPECT_LE(r.max_removed_factor, limit);
    Mesh none = in;
    o.target.max_factor = 1e-6; // below every vertex of the sphere
    EXPECT_EQ(simplify(none, o).removed, 0u);
  }
}

TEST(Simplify, AutoStopsWhenOnlyTheLastIntervalIsLeft) {
  // Two intervals: the last holds factors >= f_max / 2, so a flat terrain with one tall spike
  // keeps the spike and whatever the removals push above half of it, and removes the rest.
  Mesh in = vrs_test::grid(20, 0.2f);
  const uint32_t spike = 10 * 21 + 10;
  in.positions[3 * spike + 2] = 5.0f;
  for (int variant = 0; variant < 4; ++variant) {
    Mesh m = in;
    Options o;
    o.target.kind = TargetKind::Auto;
    o.tuning.intervals = variant & 1 ? 1000 : 2;
    o.tuning.priority = variant & 2 ? Priority::LocalError : Priority::Factor;
    Report r = simplify(m, o);
    expect_valid(in, m, r);
    EXPECT_EQ(r.stop, StopReason::LastInterval);
    EXPECT_TRUE(r.target_reached);
    EXPECT_LT(m.face_count(), in.face_count() / 4);
    // The local error of the spike's neighbours (their fans hold its steep faces) can top the
    // spike's own, so f_max and the last interval's floor are theirs: with a narrow last
    // interval the spike itself may go at the very end. The paper's factor keeps it.
    if (o.tuning.priority == Priority::Factor || o.tuning.intervals == 2) {
      EXPECT_NE(r.remap[spike], kRemoved) << variant;
    }
  }
}

TEST(Simplify, LockedVerticesStay) {
  const Mesh in = vrs_test::icosphere(2);
  std::vector<uint8_t> lock(in.vertex_count(), 0);
  for (size_t v = 0; v < lock.size(); v += 3)
    lock[v] = 1;
  Mesh m = in;
  Options o = faces(0);
  o.locked = &lock;
  Report r = simplify(m, o);
  expect_valid(in, m, r);
  for (size_t v = 0; v < lock.size(); ++v)
    if (lock[v]) {
      EXPECT_NE(r.remap[v], kRemoved) << v;
    }
  EXPECT_GT(r.removed, 0u);
}

TEST(Simplify, SameInputSameOutput) {
  const Mesh in = vrs_test::terrain(40);
  for (int variant = 0; variant < 4; ++variant) {
    Mesh a = in, b = in;
    Options o;
    o.target.ratio = 0.1;
    o.tuning.queue = variant & 1 ? QueueKind::Heap : QueueKind::Intervals;
    o.tuning.priority = variant & 2 ? Priority::Factor : Priority::LocalError;
    simplify(a, o);
    simplify(b, o);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.triangles, b.triangles);
  }
}

TEST(Simplify, ProgressIsReportedAndCanStopTheRunWithAValidMesh) {
  const Mesh in = vrs_test::icosphere(4);
  Mesh m = in;
  Options o;
  o.target.ratio = 0.05;
  std::vector<float> seen;
  o.progress = [&](float f) {
    seen.push_back(f);
    return seen.size() < 5;
  };
  Report r = simplify(m, o);
  expect_valid(in, m, r);
  EXPECT_EQ(r.stop, StopReason::Cancelled);
  EXPECT_FALSE(r.target_reached);
  ASSERT_EQ(seen.size(), 5u);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_GT(m.face_count(), size_t(0.05 * in.face_count()));
  EXPECT_LT(m.face_count(), in.face_count());
  EXPECT_EQ(vrs_test::edge_stats(m).euler(), 2);
  EXPECT_EQ(vrs_test::edge_stats(m).boundary, 0u);
}

TEST(Simplify, HeapAndLogarithmicMappingReachTheTarget) {
  const Mesh in = vrs_test::icosphere(4);
  for (int variant = 0; variant < 2; ++variant) {
    Mesh m = in;
    Options o;
    o.target.ratio = 0.02;
    if (variant)
      o.tuning.queue = QueueKind::Heap;
    else
      o.tuning.mapping = IntervalMapping::Logarithmic;
    Report r = simplify(m, o);
    expect_valid(in, m, r);
    EXPECT_TRUE(r.target_reached);
    EXPECT_EQ(vrs_test::edge_stats(m).euler(), 2);
  }
}

TEST(Simplify, FaceSourceNamesTheUntouchedInputFaces) {
  Mesh in = vrs_test::grid(6, 0.2f);
  in.triangles.insert(in.triangles.begin(), {0, 0, 1}); // dropped: shifts the indices by one
  Mesh m = in;
  Options o;
  o.target.kind = TargetKind::Faces;
  o.target.faces = 60;
  Report r = simplify(m, o);
  ASSERT_EQ(vrs_test::check_valid(in, m, r), ""); // checks each named source face
  size_t kept = 0, made = 0;
  for (uint32_t s : r.face_source)
    (s == kRemoved ? made : kept)++;
  EXPECT_GT(kept, 0u);
  EXPECT_GT(made, 0u);
  EXPECT_EQ(std::count(r.face_source.begin(), r.face_source.end(), 0u), 0); // the dropped face
}
