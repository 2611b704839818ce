// Split vertices (split_vertices.h, Options::split_vertices): a seam written as two copies of
// each vertex is simplified as one surface, and the output splits it again, each side with its
// own copies, without a crack.
#include <gtest/gtest.h>

#include <map>

#include "base/geometry.h"
#include "mesh/split_vertices.h"
#include "mesh_checks.h"
#include "test_meshes.h"

using namespace vrs;

namespace {

// The faces `side` picks take their own copy of every vertex they share with the others.
template <class Side> Mesh split(const Mesh& m, Side side) {
  Mesh out = m;
  std::vector<uint8_t> used(m.vertex_count(), 0); // bit 0: by the other faces, 1: by the side
  for (size_t f = 0; f < m.face_count(); ++f)
    for (int c = 0; c < 3; ++c)
      used[m.triangles[3 * f + c]] |= side(f) ? 2 : 1;
  std::vector<uint32_t> copy(m.vertex_count(), kRemoved);
  for (uint32_t v = 0; v < m.vertex_count(); ++v)
    if (used[v] == 3) {
      copy[v] = uint32_t(out.vertex_count());
      out.positions.insert(out.positions.end(), &m.positions[3 * v], &m.positions[3 * v] + 3);
    }
  for (size_t f = 0; f < m.face_count(); ++f)
    for (int c = 0; c < 3 && side(f); ++c) {
      uint32_t& v = out.triangles[3 * f + c];
      if (copy[v] != kRemoved) v = copy[v];
    }
  return out;
}

// Every face with three vertices of its own.
Mesh soup(const Mesh& m) {
  Mesh out;
  for (uint32_t v : m.triangles) {
    out.triangles.push_back(uint32_t(out.vertex_count()));
    out.positions.insert(out.positions.end(), &m.positions[3 * v], &m.positions[3 * v] + 3);
  }
  return out;
}

bool upper(const Mesh& m, size_t f) {
  float z = 0;
  for (int c = 0; c < 3; ++c)
    z += m.positions[3 * m.triangles[3 * f + c] + 2];
  return z > 0;
}

// Output vertex -> input vertex.
std::vector<uint32_t> input_of(const Report& r, size_t out_vertices) {
  std::vector<uint32_t> in(out_vertices, kRemoved);
  for (size_t i = 0; i < r.remap.size(); ++i)
    if (r.remap[i] != kRemoved) in[r.remap[i]] = uint32_t(i);
  return in;
}

} // namespace

TEST(SplitVertices, ASeamIsSimplifiedAsOneSurfaceAndEachSideKeepsItsCopies) {
  const Mesh whole = vrs_test::icosphere(3);
  const Mesh in = split(whole, [&](size_t f) { return upper(whole, f); });
  const size_t copies = in.vertex_count() - whole.vertex_count();
  ASSERT_GT(copies, 10u);
  // Which side each input vertex belongs to: the copies and what only upper faces use.
  std::vector<int> side(in.vertex_count(), 0);
  for (size_t f = 0; f < in.face_count(); ++f)
    for (int c = 0; c < 3; ++c)
      if (upper(whole, f)) side[in.triangles[3 * f + c]] = 1;
  for (double ratio : {0.5, 0.1}) {
    Options o;
    o.target.ratio = ratio;
    Mesh out = in;
    const Report r = simplify(out, o);
    EXPECT_EQ(r.welded_vertices, copies);
    EXPECT_TRUE(r.target_reached) << ratio << ": " << r.stop_detail;
    EXPECT_EQ(vrs_test::check_run(in, out, o, r), "") << ratio;
    const auto from = input_of(r, out.vertex_count());
    size_t seam_removed = 0;
    for (uint32_t v = uint32_t(whole.vertex_count()); v < in.vertex_count(); ++v)
      seam_removed += r.remap[v] == kRemoved;
    EXPECT_GT(seam_removed, 0u) << "the seam simplified along itself";
    for (size_t f = 0; f < out.face_count(); ++f) {
      const int s = side[from[out.triangles[3 * f]]];
      for (int c = 1; c < 3; ++c)
        EXPECT_EQ(side[from[out.triangles[3 * f + c]]], s) << "face " << f << " spans the seam";
    }
    for (const auto& [edge, n] : vrs_test::edges_by_position(out))
      ASSERT_EQ(n, 2) << "a crack along the seam";
  }
}

TEST(SplitVertices, PiecesWrittenInOtherOrientationsAreWeldedAndKeepTheirOwn) {
  // A CAD export's panels, each written in its own orientation (CGAL's boeing): the lower
  // half's faces turned over, its seam split. Left apart, every vertex of the seam was a twin
  // on a border, kept; welded the same way (this run), the halves are one surface, the seam
  // stays (no face across two orientations) and each face is written as its input was.
  const Mesh whole = vrs_test::icosphere(3);
  Mesh in = split(whole, [&](size_t f) { return upper(whole, f); });
  for (size_t f = 0; f < in.face_count(); ++f)
    if (!upper(whole, f)) std::swap(in.triangles[3 * f + 1], in.triangles[3 * f + 2]);
  const size_t copies = in.vertex_count() - whole.vertex_count();
  std::vector<int> side(in.vertex_count(), 0); // 1: a vertex of the upper half's faces only
  for (size_t f = 0; f < in.face_count(); ++f)
    for (int c = 0; c < 3; ++c)
      if (upper(whole, f)) side[in.triangles[3 * f + c]] = 1;
  for (SplitVertices mode : {SplitVertices::Weld, SplitVertices::Seam}) {
    Options o;
    o.target.ratio = 0.1;
    o.split_vertices = mode;
    o.corner_sources = true;
    Mesh out = in;
    const Report r = simplify(out, o);
    EXPECT_EQ(r.welded_vertices, copies);
    EXPECT_EQ(r.reoriented_faces, 0u) << "the output holds every face as its input was";
    EXPECT_TRUE(r.target_reached) << r.stop_detail;
    EXPECT_EQ(vrs_test::check_run(in, out, o, r), "");
    size_t seam_removed = 0;
    for (uint32_t v = uint32_t(whole.vertex_count()); v < in.vertex_count(); ++v)
      seam_removed += r.remap[v] == kRemoved;
    EXPECT_GT(seam_removed, 0u) << "the seam simplified along itself";
    const auto from = input_of(r, out.vertex_count());
    for (size_t f = 0; f < out.face_count(); ++f) {
      const uint32_t* t = &out.triangles[3 * f];
      const int s = side[from[t[0]]];
      for (int c = 1; c < 3; ++c)
        EXPECT_EQ(side[from[t[c]]], s) << "face " << f << " spans the seam";
      // Outward on the upper half, inward on the lower, as written.
      Vec3 p[3];
      for (int c = 0; c < 3; ++c)
        p[c] = {out.positions[3 * t[c]], out.positions[3 * t[c] + 1], out.positions[3 * t[c] + 2]};
      const double outward = dot(cross(p[1] - p[0], p[2] - p[0]), p[0] + p[1] + p[2]);
      EXPECT_EQ(outward > 0, s == 1) << "face " << f << " turned against its input";
      // Its corners' data from input faces of its own half.
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(upper(whole, r.corner_source[3 * f + c] / 3), s == 1) << "face " << f;
    }
    for (const auto& [edge, n] : vrs_test::edges_by_position(out))
      ASSERT_EQ(n, 2) << "a crack along the seam";
  }
}

TEST(SplitVertices, AShuffledMeshWithASplitSeamComesOutCoherent) {
  // Faces written in random orientation (every third turned) are turned to agree, as without
  // split vertices: only whole pieces written in another orientation are given it back.
  const Mesh whole = vrs_test::icosphere(3);
  Mesh in = split(whole, [&](size_t f) { return upper(whole, f); });
  for (size_t f = 0; f < in.face_count(); f += 3)
    std::swap(in.triangles[3 * f + 1], in.triangles[3 * f + 2]);
  Options o;
  o.target.ratio = 0.1;
  o.split_vertices = SplitVertices::Weld;
  Mesh out = in;
  const Report r = simplify(out, o);
  EXPECT_EQ(r.welded_vertices, in.vertex_count() - whole.vertex_count());
  EXPECT_EQ(r.reoriented_faces, (in.face_count() + 2) / 3);
  EXPECT_TRUE(r.target_reached) << r.stop_detail;
  EXPECT_EQ(vrs_test::check_run(in, out, o, r), "");
  for (size_t f = 0; f < out.face_count(); ++f) {
    Vec3 p[3];
    for (int c = 0; c < 3; ++c)
      p[c] = {out.positions[3 * out.triangles[3 * f + c]],
              out.positions[3 * out.triangles[3 * f + c] + 1],
              out.positions[3 * out.triangles[3 * f + c] + 2]};
    EXPECT_GT(dot(cross(p[1] - p[0], p[2] - p[0]), p[0] + p[1] + p[2]), 0) << "face " << f;
  }
}

TEST(SplitVertices, KeepLeavesTheCopiesApart) {
  const Mesh whole = vrs_test::icosphere(3);
  const Mesh in = split(whole, [&](size_t f) { return upper(whole, f); });
  Options o;
  o.target.ratio = 0.1;
  o.split_vertices = SplitVertices::Keep;
  Mesh out = in;
  const Report r = simplify(out, o);
  EXPECT_EQ(r.welded_vertices, 0u);
  EXPECT_EQ(vrs_test::check_run(in, out, o, r), "");
  for (uint32_t v = uint32_t(whole.vertex_count()); v < in.vertex_count(); ++v)
    EXPECT_NE(r.remap[v], kRemoved) << "a copy on the seam went";
}

TEST(SplitVertices, ASoupOfFacesIsWeldedIntoItsSurface) {
  const Mesh in = soup(vrs_test::icosphere(2));
  Options o;
  o.target.ratio = 0.1;
  o.split_vertices = SplitVertices::Weld;
  o.corner_sources = true;
  Mesh out = in;
  const Report r = simplify(out, o);
  EXPECT_EQ(r.welded_vertices, in.vertex_count() - vrs_test::icosphere(2).vertex_count());
  EXPECT_TRUE(r.target_reached) << r.stop_detail;
  EXPECT_EQ(vrs_test::check_run(in, out, o, r), "");
  for (const auto& [edge, n] : vrs_test::edges_by_position(out))
    ASSERT_EQ(n, 2) << "the output is not closed";
  // Each corner is the copy its input corner had.
  const auto from = input_of(r, out.vertex_count());
  for (size_t i = 0; i < out.triangles.size(); ++i)
    EXPECT_EQ(in.triangles[r.corner_source[i]], from[out.triangles[i]]) << "corner " << i;
  // Seam mode keeps every face's copies: each face its own chart, nothing to remove.
  o.split_vertices = SplitVertices::Seam;
  Mesh seam = in;
  const Report rs = simplify(seam, o);
  EXPECT_EQ(vrs_test::check_run(in, seam, o, rs), "");
  EXPECT_EQ(seam.face_count(), in.face_count());
  // ... and the report says what welds it.
  EXPECT_NE(rs.stop_detail.find("most seams are where split vertices meet"), std::string::npos)
      << rs.stop_detail;
  EXPECT_NE(rs.stop_detail.find("split_vertices weld welds them freely"), std::string::npos)
      << rs.stop_detail;
}

TEST(SplitVertices, ALockedCopyKeepsTheVertexAndEveryCopy) {
  const Mesh whole = vrs_test::icosphere(3);
  const Mesh in = split(whole, [&](size_t f) { return upper(whole, f); });
  std::vector<uint8_t> locked(in.vertex_count(), 0);
  const uint32_t copy = uint32_t(whole.vertex_count()); // the first copy
  locked[copy] = 1;
  Options o;
  o.target.ratio = 0.05;
  o.locked = &locked;
  Mesh out = in;
  const Report r = simplify(out, o);
  EXPECT_EQ(vrs_test::check_run(in, out, o, r), "");
  EXPECT_NE(r.remap[copy], kRemoved);
  // Its twin: the original vertex at the same position.
  for (uint32_t v = 0; v < whole.vertex_count(); ++v) {
    if (std::equal(&in.positions[3 * v], &in.positions[3 * v] + 3, &in.positions[3 * copy])) {
      EXPECT_NE(r.remap[v], kRemoved) << "the locked copy's twin went";
    }
  }
}

TEST(SplitVertices, WithoutCopiesTheRunIsTheSameInEveryMode) {
  const Mesh in = vrs_test::icosphere(3);
  Mesh keep = in, seam = in;
  Options o;
  o.target.ratio = 0.1;
  const Report rs = simplify(seam, o);
  o.split_vertices = SplitVertices::Keep;
  const Report rk = simplify(keep, o);
  EXPECT_EQ(rs.welded_vertices, 0u);
  EXPECT_TRUE(vrs_test::same_bits(keep, seam));
}

TEST(SplitVertices, AFaceThatWouldHoldOneVertexTwiceKeepsItsCopiesApart) {
  // Two triangles side by side, their shared edge split; a sliver joins the two copies of one
  // end: welding that end would give the sliver a repeated corner.
  Mesh m;
  m.positions = {0, 0,  0, 1,    0, 0, 0.5f, 1, 0, // 0 1 2: left triangle
                 1, 0,  0, 0.5f, 1, 0, 1.5f, 1, 0, // 3 4 5: copies of 1, 2 and a new corner
                 1, -1, 0};                        // 6
  m.triangles = {0, 1, 2, 3, 5, 4, 1, 6, 3};
  const Welding w = weld_split_vertices(m.triangles, m.positions);
  for (size_t i = 0; i + 2 < m.triangles.size(); i += 3) {
    EXPECT_NE(m.triangles[i], m.triangles[i + 1]);
    EXPECT_NE(m.triangles[i + 1], m.triangles[i + 2]);
    EXPECT_NE(m.triangles[i + 2], m.triangles[i]);
  }
  // 1 and 3 stay apart; 2 and 4 are welded (their edge pairs with 1-2's), a vertex where two
  // fans touch, which the run then keeps.
  EXPECT_EQ(w.welded, 1u);
  EXPECT_EQ(m.triangles[0] == m.triangles[6] ? 1 : 0, 0) << "1 was welded to 3";
  Mesh in = m, out = m;
  in.triangles = {0, 1, 2, 3, 5, 4, 1, 6, 3};
  out = in;
  Options o;
  o.target.ratio = 0.5;
  const Report r = simplify(out, o);
  EXPECT_EQ(vrs_test::check_run(in, out, o, r), "");
}
