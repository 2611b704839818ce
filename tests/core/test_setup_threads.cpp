// The set-up's steps split over the workers by ranges of vertices (topology, spatial order,
// welding) or fixed blocks (sums): each gives what one thread gives, bit for bit, whatever the
// thread count, so the run's output cannot depend on it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "base/workers.h"
#include "evaluate/local_error.h"
#include "mesh/spatial_order.h"
#include "mesh/split_vertices.h"
#include "mesh/topology.h"
#include "test_meshes.h"

using namespace vrs;

namespace {

// Faces in random order and a hub of 3000 faces (a fan around one apex): lists that no
// spatial order makes easy, and a list past kHubFaces.
Mesh shuffled_with_a_hub() {
  Mesh m = vrs_test::icosphere(5);
  const uint32_t apex = uint32_t(m.vertex_count());
  m.positions.insert(m.positions.end(), {0.0f, 0.0f, 3.0f});
  for (uint32_t i = 0; i < 3000; ++i) {
    const float a = 6.2831853f * float(i) / 3000.0f;
    m.positions.insert(m.positions.end(), {2.0f * std::cos(a), 2.0f * std::sin(a), 2.5f});
  }
  for (uint32_t i = 0; i < 3000; ++i)
    m.triangles.insert(m.triangles.end(), {apex, apex + 1 + i, apex + 1 + (i + 1) % 3000});
  std::vector<uint32_t> order(m.face_count());
  for (uint32_t f = 0; f < order.size(); ++f)
    order[f] = f;
  std::shuffle(order.begin(), order.end(), std::mt19937(11));
  std::vector<uint32_t> t(m.triangles.size());
  for (size_t f = 0; f < order.size(); ++f)
    for (int c = 0; c < 3; ++c)
      t[3 * f + c] = m.triangles[3 * size_t(order[f]) + c];
  m.triangles.swap(t);
  return m;
}

Mesh soup(const Mesh& m) { // every face its own three copies
  Mesh s;
  for (uint32_t c : m.triangles) {
    for (int a = 0; a < 3; ++a)
      s.positions.push_back(m.positions[3 * size_t(c) + a]);
    s.triangles.push_back(uint32_t(s.triangles.size()));
  }
  return s;
}

} // namespace

TEST(SetupThreads, TopologyListsAreTheSameOnAnyNumberOfThreads) {
  const Mesh m = shuffled_with_a_hub();
  Topology one;
  one.build(m.triangles, m.vertex_count());
  for (int threads : vrs_test::compared_thread_counts()) {
    Workers workers(threads);
    Topology many;
    many.build(m.triangles, m.vertex_count(), &workers);
    ASSERT_EQ(many.vertex_count(), one.vertex_count());
    for (uint32_t v = 0; v < m.vertex_count(); ++v) {
      ASSERT_EQ(many.valence(v), one.valence(v)) << "vertex " << v;
      for (uint32_t i = 0; i < one.valence(v); ++i)
        ASSERT_EQ(many.faces_of(v)[i], one.faces_of(v)[i]) << "vertex " << v;
      // In face order: rings and every later edit read them so.
      for (uint32_t i = 1; i < many.valence(v); ++i)
        ASSERT_LT(many.faces_of(v)[i - 1], many.faces_of(v)[i]) << "vertex " << v;
    }
    Ring a, b;
    const uint32_t apex = uint32_t(m.vertex_count() - 3001);
    EXPECT_EQ(many.ring(apex, m.triangles.data(), kMaxRing, a), VertexKind::HighValence);
    EXPECT_TRUE(many.has_edge(apex, apex + 1, m.triangles.data())); // through the hub's map
    EXPECT_EQ(many.ring(0, m.triangles.data(), kMaxRing, a),
              one.ring(0, m.triangles.data(), kMaxRing, b));
  }
}

TEST(SetupThreads, SpatialOrderIsTheSameOnAnyNumberOfThreads) {
  Mesh base = vrs_test::icosphere(7); // 163 842 vertices: several blocks and ranges
  base.positions[7] = std::numeric_limits<float>::quiet_NaN(); // ordered last, by index
  Mesh one = base;
  const SpatialOrder o1 = spatial_order(one.positions, one.triangles, nullptr);
  for (int threads : {2, 3}) {
    Workers workers(threads);
    Mesh many = base;
    const SpatialOrder o = spatial_order(many.positions, many.triangles, &workers);
    EXPECT_EQ(o.vertex_new, o1.vertex_new);
    EXPECT_EQ(o.face_old, o1.face_old);
    EXPECT_EQ(many.triangles, one.triangles);
    EXPECT_EQ(0, std::memcmp(many.positions.data(), one.positions.data(),
                             sizeof(float) * one.positions.size()));
  }
  // Faces by their lowest new corner, stable: the counting sort's order.
  for (size_t f = 1; f < one.face_count(); ++f) {
    auto lowest = [&](size_t g) {
      return std::min({one.triangles[3 * g], one.triangles[3 * g + 1], one.triangles[3 * g + 2]});
    };
    ASSERT_TRUE(lowest(f - 1) < lowest(f) ||
                (lowest(f - 1) == lowest(f) && o1.face_old[f - 1] < o1.face_old[f]))
        << "face " << f;
  }
}

TEST(SetupThreads, WeldingIsTheSameOnAnyNumberOfThreads) {
  const Mesh in = soup(vrs_test::icosphere(4));
  Mesh one = in;
  const Welding w1 = weld_split_vertices(one.triangles, one.positions);
  EXPECT_EQ(w1.welded, in.vertex_count() - vrs_test::icosphere(4).vertex_count());
  for (int threads : vrs_test::compared_thread_counts()) {
    Workers workers(threads);
    Mesh many = in;
    const Welding w = weld_split_vertices(many.triangles, many.positions, &workers);
    EXPECT_EQ(w.rep, w1.rep);
    EXPECT_EQ(w.welded, w1.welded);
    EXPECT_EQ(w.seams, w1.seams);
    EXPECT_EQ(many.triangles, one.triangles);
  }
}

TEST(SetupThreads, MeanTriangleAreaIsTheSameOnAnyNumberOfThreads) {
  const Mesh m = vrs_test::icosphere(7);
  const double one = mean_triangle_area(m.positions.data(), m.triangles);
  for (int threads : {2, 3}) {
    Workers workers(threads);
    EXPECT_EQ(mean_triangle_area(m.positions.data(), m.triangles, &workers), one);
  }
  EXPECT_NEAR(one * double(m.face_count()), 4 * 3.14159265, 0.01); // a unit sphere's area
}
