// Simplification by parts (parts.h): the cut keeps each part's removals inside it, the part's
// queue pops in price order, and the output is the same whatever the thread count, with every
// invariant of a run.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "driver/parts.h"
#include "mesh/spatial_order.h"
#include "mesh_checks.h"
#include "test_meshes.h"

using namespace vrs;

TEST(Parts, AVertexLeftFreeHasItsWholeNeighbourhoodInItsPart) {
  Mesh m = vrs_test::icosphere(5);         // 10242 vertices
  spatial_order(m.positions, m.triangles); // as the driver cuts it
  Topology topo;
  topo.build(m.triangles, m.vertex_count());
  for (uint32_t shift : {0u, 128u}) {
    const Parts parts = make_parts(m.triangles, topo, 256, shift);
    ASSERT_EQ(parts.count, (m.vertex_count() + shift + 255) / 256);
    size_t free = 0;
    for (size_t i = 0; i < m.triangles.size(); i += 3) {
      const uint32_t* t = &m.triangles[i];
      const bool some_free = !parts.frozen[t[0]] || !parts.frozen[t[1]] || !parts.frozen[t[2]];
      if (!some_free) continue;
      ++free;
      // A free vertex's faces lie in its part, and none of their corners has a neighbour
      // elsewhere (whose ring another part could change).
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(parts.of(t[c]), parts.of(t[0])) << "face " << i / 3;
        EXPECT_FALSE(parts.frozen[t[c]] & 2) << "face " << i / 3;
      }
    }
    EXPECT_GT(free, m.triangles.size() / 3 / 4) << "the cut froze nearly everything";
    for (size_t p = 0; p < parts.count; ++p) // the parts tile the vertices
      EXPECT_EQ(p + 1 < parts.count ? parts.end(p, m.vertex_count()) : m.vertex_count(),
                p + 1 < parts.count ? parts.first(p + 1) : m.vertex_count());
  }
}

TEST(Parts, APartsQueuePopsInPriceOrderThenInsertionOrder) {
  PartQueue q;
  q.init(1000, 500);
  std::map<std::pair<float, int>, uint32_t> reference; // (price, insertion) -> vertex
  std::map<uint32_t, std::pair<float, int>> where;
  std::mt19937 rng(7);
  int inserted = 0;
  for (int step = 0; step < 5000; ++step) {
    const uint32_t v = 1000 + rng() % 500;
    if (rng() % 3 == 0) {
      q.erase(v);
      if (where.count(v)) reference.erase(where[v]), where.erase(v);
    } else {
      const float f = float(rng() % 50); // many ties
      q.push(v, f);
      if (where.count(v)) reference.erase(where[v]);
      where[v] = {f, inserted++};
      reference[where[v]] = v;
    }
    ASSERT_EQ(q.contains(v), where.count(v) == 1);
    if (!reference.empty()) {
      ASSERT_EQ(q.front(), reference.begin()->second);
      ASSERT_EQ(q.front_factor(), reference.begin()->first.first);
    }
  }
  size_t under = 0;
  for (const auto& e : reference)
    under += e.first.first <= 20;
  EXPECT_EQ(q.count_at_most(20), under);
  while (!reference.empty()) {
    ASSERT_EQ(q.front(), reference.begin()->second);
    q.erase(q.front());
    reference.erase(reference.begin());
  }
  EXPECT_TRUE(q.empty());
}

namespace {

Report run(Mesh& m, Options o, int threads) {
  o.threads = threads;
  return simplify(m, o);
}

} // namespace

TEST(Parts, SameOutputWhateverTheThreadCountAndEveryInvariantKept) {
  const auto cases = vrs_test::comparison_meshes();
  ASSERT_GE(cases.size(), 5u) << "CGAL's data set is missing";
  for (const auto& c : cases)
    for (int variant = 0; variant < 5; ++variant) {
      Options o;
      o.tuning.part_vertices = 64;  // small parts: these meshes are cut into dozens
      o.tuning.lazy_from_faces = 0; // the parts run with lazy prices, here on small meshes too
      o.target.ratio = variant == 4 ? 0.01 : 0.1;
      o.corner_sources = true;
      if (variant == 1) o.simplify_boundary = true;
      if (variant == 2) o.feature_angle_deg = 40; // seams stay frozen in the parts
      if (variant == 3) {
        o.target.kind = TargetKind::Vertices;
        o.target.vertices = c.mesh.vertex_count() / 4;
      }
      const std::string what = c.name + " variant " + std::to_string(variant);
      Mesh one = c.mesh;
      const Report r1 = run(one, o, 1);
      ASSERT_TRUE(r1.ok) << r1.message;
      ASSERT_EQ(vrs_test::check_run(c.mesh, one, o, r1), "") << what;
      if (variant != 4 && variant != 2) {
        EXPECT_TRUE(r1.target_reached) << what;
      }
      // The parts ran: one queue from the start ends elsewhere.
      Options whole = o;
      whole.tuning.part_vertices = 0;
      Mesh w = c.mesh;
      run(w, whole, 1);
      EXPECT_FALSE(vrs_test::same_bits(one, w)) << what << ": the parts did not run";
      for (int threads : vrs_test::compared_thread_counts()) {
        Mesh m = c.mesh;
        const Report r = run(m, o, threads);
        EXPECT_TRUE(vrs_test::same_bits(one, m)) << what << ", " << threads << " threads";
        EXPECT_EQ(r.removed, r1.removed) << what;
        EXPECT_EQ(r.stop_detail, r1.stop_detail) << what;
        EXPECT_EQ(r.corner_source, r1.corner_source) << what;
        for (int k = 0; k < RejectCount; ++k)
          EXPECT_EQ(r.rejected[k], r1.rejected[k]) << what << ", " << reject_name(Reject(k));
      }
    }
}

TEST(Parts, CancellingWhileThePartsRunLeavesAValidMeshTheSameOnAnyThreads) {
  const Mesh in = vrs_test::icosphere(5);
  std::vector<Mesh> outs;
  for (int threads : {1, 2}) {
    Options o;
    o.tuning.part_vertices = 256;
    o.tuning.lazy_from_faces = 0;
    o.target.ratio = 0.05;
    o.threads = threads;
    int calls = 0;
    o.progress = [&](float) { return ++calls < 2; }; // the second round's report says stop
    Mesh m = in;
    const Report r = simplify(m, o);
    ASSERT_EQ(r.stop, StopReason::Cancelled);
    ASSERT_EQ(vrs_test::check_valid(in, m, r), "");
    EXPECT_LT(m.face_count(), in.face_count());
    outs.push_back(m);
  }
  EXPECT_TRUE(vrs_test::same_bits(outs[0], outs[1]));
}

TEST(Parts, ABadPartSizeIsRefused) {
  const Mesh in = vrs_test::icosphere(2);
  for (int size : {-1, 1, 63}) {
    Mesh m = in;
    Options o;
    o.tuning.part_vertices = size;
    const Report r = simplify(m, o);
    EXPECT_FALSE(r.ok) << size;
    EXPECT_NE(r.message.find("part vertices"), std::string::npos) << r.message;
    EXPECT_TRUE(vrs_test::same_bits(in, m));
  }
}
