// Nested levels of detail (vrs/lods.h): every level a subset of the finer one, the shared
// vertex order coarsest first with each level a prefix, the maps back to the input true, and
// seams of per-corner data kept through every level.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "mesh_checks.h"
#include "test_meshes.h"
#include "vrs/lods.h"

using namespace vrs;

namespace {

// The level as a mesh of input positions (its prefix of the shared order).
Mesh level_mesh(const Mesh& in, const LodChain& chain, const LodLevel& l) {
  Mesh m;
  for (size_t i = 0; i < l.vertex_count; ++i)
    for (int c = 0; c < 3; ++c)
      m.positions.push_back(in.positions[3 * chain.vertices[i] + c]);
  m.triangles = l.triangles;
  return m;
}

Mesh real_or_sphere(const char* name) {
  Mesh m = vrs_test::read_off(vrs_test::cgal_mesh(name));
  return m.face_count() ? m : vrs_test::icosphere(5);
}

} // namespace

TEST(Lods, LevelsNestAndEachIsAPrefixOfTheSharedOrder) {
  const Mesh in = real_or_sphere("elephant.off");
  Options o;
  o.threads = 1;
  const LodChain chain = simplify_lods(in, {0.01, 1.0, 0.1, 0.5}, o);
  ASSERT_TRUE(chain.ok) << chain.message;
  ASSERT_EQ(chain.levels.size(), 4u);
  const double asked[] = {1.0, 0.5, 0.1, 0.01};
  std::set<uint32_t> finer;
  for (size_t L = 0; L < 4; ++L) {
    const LodLevel& l = chain.levels[L];
    EXPECT_EQ(l.ratio, asked[L]);
    if (l.report.target_reached) {
      EXPECT_LE(l.triangles.size() / 3, size_t(asked[L] * double(in.face_count()))) << L;
    } else { // stopped short, and says why
      EXPECT_FALSE(l.report.stop_detail.empty()) << L;
    }
    if (L > 0) {
      EXPECT_LE(l.vertex_count, chain.levels[L - 1].vertex_count);
    }
    std::set<uint32_t> used;
    for (uint32_t v : l.triangles) {
      ASSERT_LT(v, l.vertex_count) << "level " << L << " reads past its prefix";
      used.insert(chain.vertices[v]);
    }
    EXPECT_EQ(used.size(), l.vertex_count) << "a prefix holds only the level's own vertices";
    for (uint32_t v : used) {
      if (L > 0) {
        EXPECT_TRUE(finer.count(v)) << "vertex " << v << " is not in the finer level";
      }
    }
    finer = used;
    // Every face with a source is that input face, corners in order up to rotation.
    for (size_t f = 0; f < l.face_source.size(); ++f) {
      if (l.face_source[f] == kRemoved) continue;
      std::multiset<uint32_t> a, b;
      for (int c = 0; c < 3; ++c) {
        a.insert(chain.vertices[l.triangles[3 * f + c]]);
        b.insert(in.triangles[3 * l.face_source[f] + c]);
      }
      ASSERT_EQ(a, b) << "level " << L << " face " << f;
    }
    // A valid surface of the input's topology.
    const Mesh m = level_mesh(in, chain, l);
    EXPECT_EQ(vrs_test::check_indices(m), "");
    EXPECT_LE(vrs_test::edge_stats(m).nonmanifold, vrs_test::edge_stats(in).nonmanifold);
    EXPECT_EQ(vrs_test::count_duplicate_directed_edges(m), 0u);
    EXPECT_EQ(vrs_test::component_euler(m), vrs_test::component_euler(in)) << L;
  }
  // The finest level at ratio 1 is the input itself.
  EXPECT_EQ(chain.levels[0].triangles.size(), in.triangles.size());
  EXPECT_EQ(chain.vertices.size(), in.vertex_count());
}

TEST(Lods, EachLevelIsTheRunOfTheFinerLevel) {
  // A level is exactly what simplify() makes of the finer level, priced as the input is
  // (lazily from Tuning::lazy_from_faces on, even where a level is smaller): the chain adds
  // nothing.
  const Mesh in = vrs_test::icosphere(4); // 5120 faces; the first level 2560
  for (size_t lazy_from : {size_t(4000), Tuning().lazy_from_faces}) {
    Options o;
    o.threads = 1;
    o.tuning.lazy_from_faces = lazy_from;
    const LodChain chain = simplify_lods(in, {0.5, 0.2}, o);
    ASSERT_TRUE(chain.ok);
    // The two runs by hand, each level's faces in input vertex ids.
    Options a = o;
    a.target.kind = TargetKind::Faces;
    if (in.face_count() >= lazy_from)
      a.tuning.lazy_from_faces = 0; // lazy
    else
      a.tuning.lazy_reevaluation = false; // eager
    std::vector<uint32_t> ids(in.vertex_count());
    for (uint32_t v = 0; v < ids.size(); ++v)
      ids[v] = v;
    Mesh m = in;
    for (size_t L = 0; L < 2; ++L) {
      a.target.faces = size_t(chain.levels[L].ratio * double(in.face_count()));
      const Report r = simplify(m, a);
      std::vector<uint32_t> next(m.vertex_count());
      for (size_t v = 0; v < r.remap.size(); ++v)
        if (r.remap[v] != kRemoved) next[r.remap[v]] = ids[v];
      ids = next;
      std::vector<uint32_t> by_hand, chained;
      for (uint32_t v : m.triangles)
        by_hand.push_back(ids[v]);
      for (uint32_t v : chain.levels[L].triangles)
        chained.push_back(chain.vertices[v]);
      EXPECT_EQ(chained, by_hand) << "level " << L << ", lazy from " << lazy_from;
    }
    // Same run twice: same chain.
    const LodChain again = simplify_lods(in, {0.5, 0.2}, o);
    EXPECT_EQ(again.vertices, chain.vertices);
    EXPECT_EQ(again.levels[1].triangles, chain.levels[1].triangles);
  }
}

TEST(Lods, SeamsOfCornerKeysAreKeptAtEveryLevel) {
  // A grid whose left and right halves are two texture charts: every face of every level
  // takes its three corners from one chart, and the seam column stays a polyline.
  const int n = 24;
  const Mesh in = vrs_test::grid(n, 0.2f);
  std::vector<uint32_t> keys(in.triangles.size());
  auto chart_of_face = [&](size_t f) {
    float x = 0;
    for (int c = 0; c < 3; ++c)
      x += in.positions[3 * in.triangles[3 * f + c]];
    return x / 3 < in.positions[3 * (n / 2)] ? 0u : 1u; // left or right of column n/2
  };
  for (size_t f = 0; f < in.face_count(); ++f)
    for (int c = 0; c < 3; ++c)
      keys[3 * f + c] = chart_of_face(f) * 100000 + in.triangles[3 * f + c];
  Options o;
  o.threads = 1;
  o.simplify_boundary = true;
  const LodChain chain = simplify_lods(in, {0.5, 0.1, 0.02}, o, &keys);
  ASSERT_TRUE(chain.ok) << chain.message;
  for (const LodLevel& l : chain.levels) {
    ASSERT_EQ(l.corner_source.size(), l.triangles.size());
    size_t faces_left = 0;
    for (size_t f = 0; f < l.triangles.size() / 3; ++f) {
      std::set<uint32_t> charts;
      for (int c = 0; c < 3; ++c) {
        const uint32_t s = l.corner_source[3 * f + c];
        ASSERT_EQ(in.triangles[s], chain.vertices[l.triangles[3 * f + c]])
            << "a corner takes the data of another vertex";
        charts.insert(keys[s] / 100000);
      }
      EXPECT_EQ(charts.size(), 1u) << "face " << f << " spans both charts";
      faces_left += charts.count(0);
    }
    EXPECT_GT(faces_left, 0u);
    EXPECT_LT(faces_left, l.triangles.size() / 3);
  }
  EXPECT_LT(chain.levels.back().triangles.size(), chain.levels.front().triangles.size());
}

TEST(Lods, ConstrainedPolylinesAreFollowedThroughTheLevels) {
  // A constrained line across a grid (the middle row): its vertices may go along it, and
  // whatever is left of it is still an edge chain at the coarsest level.
  const int n = 20;
  const Mesh in = vrs_test::grid(n, 0.0f);
  std::vector<uint32_t> row;
  for (int x = 0; x + 1 <= n; ++x)
    row.insert(row.end(), {uint32_t((n / 2) * (n + 1) + x), uint32_t((n / 2) * (n + 1) + x + 1)});
  Options o;
  o.threads = 1;
  o.constrained_edges = &row;
  o.simplify_boundary = true;
  const LodChain chain = simplify_lods(in, {0.5, 0.1}, o);
  ASSERT_TRUE(chain.ok) << chain.message;
  const LodLevel& coarse = chain.levels.back();
  // Every face lies on one side of the row (none straddles it).
  const float y_row = in.positions[3 * ((n / 2) * (n + 1)) + 1];
  for (size_t f = 0; f < coarse.triangles.size() / 3; ++f) {
    bool above = false, below = false;
    for (int c = 0; c < 3; ++c) {
      const float y = in.positions[3 * chain.vertices[coarse.triangles[3 * f + c]] + 1];
      above |= y > y_row + 1e-6f;
      below |= y < y_row - 1e-6f;
    }
    EXPECT_FALSE(above && below) << "face " << f << " crosses the constrained row";
  }
}

TEST(Lods, BadLevelsAreRefusedWithAMessage) {
  const Mesh in = vrs_test::icosphere(2);
  Options o;
  for (const std::vector<double>& bad :
       {std::vector<double>{}, {0.5, 0.0}, {1.5}, {std::nan("")}}) {
    const LodChain c = simplify_lods(in, bad, o);
    EXPECT_FALSE(c.ok);
    EXPECT_FALSE(c.message.empty());
  }
  std::vector<uint32_t> short_keys(3);
  EXPECT_FALSE(simplify_lods(in, {0.5}, o, &short_keys).ok);
  Mesh broken = in;
  broken.triangles[0] = 1u << 30;
  const LodChain c = simplify_lods(broken, {0.5}, o);
  EXPECT_FALSE(c.ok);
  EXPECT_FALSE(c.message.empty());
}
