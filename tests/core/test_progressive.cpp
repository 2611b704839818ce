// The progressive mesh (vrs/progressive.h): the base is the run's output, every insertion
// applied gives back the input slot by slot, and every prefix is a valid mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

#include "mesh/corner_seams.h"
#include "test_meshes.h"
#include "vrs/progressive.h"

using namespace vrs;

namespace {

constexpr uint32_t kChartSpan = 100000; // corner keys: chart * kChartSpan + vertex

// A face's corners rotated to start at the lowest.
std::array<uint32_t, 3> rotated(const uint32_t* c) {
  const int k = c[0] <= c[1] && c[0] <= c[2] ? 0 : c[1] <= c[2] ? 1 : 2;
  return {c[k], c[(k + 1) % 3], c[(k + 2) % 3]};
}

// What is wrong with the faces of a prefix (empty: nothing): a face with a repeated vertex, a
// directed edge twice (two faces disagreeing on orientation, or the same face twice), an edge
// of more than two faces where the input has none.
std::string check_prefix(const Mesh& in, const std::vector<uint32_t>& slots, size_t input_worst) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  std::map<std::pair<uint32_t, uint32_t>, int> undirected;
  for (size_t s = 0; s < slots.size() / 3; ++s) {
    if (slots[3 * s] == kEmptySlot) continue;
    uint32_t v[3];
    for (int c = 0; c < 3; ++c)
      v[c] = in.triangles[slots[3 * s + c]];
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
      return "slot " + std::to_string(s) + " repeats a vertex";
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = v[c], b = v[(c + 1) % 3];
      if (++directed[{a, b}] > 1)
        return "directed edge " + std::to_string(a) + "-" + std::to_string(b) + " twice";
      ++undirected[{std::min(a, b), std::max(a, b)}];
    }
  }
  for (const auto& [e, n] : undirected)
    if (n > 2 && size_t(n) > input_worst) return "an edge of " + std::to_string(n) + " faces";
  return "";
}

size_t worst_edge(const Mesh& m) {
  std::map<std::pair<uint32_t, uint32_t>, size_t> count;
  size_t worst = 0;
  for (size_t i = 0; i < m.triangles.size(); i += 3)
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = m.triangles[i + c], b = m.triangles[i + (c + 1) % 3];
      worst = std::max(worst, ++count[{std::min(a, b), std::max(a, b)}]);
    }
  return worst;
}

// The whole check of one run: the base is simplify()'s output without the slide, each of
// `probes` prefixes is valid, and all insertions give back every input face in its slot.
void check_progressive(const std::string& name, const Mesh& in, const Options& o,
                       const std::vector<uint32_t>* keys = nullptr, size_t probes = 12) {
  SCOPED_TRACE(name);
  const ProgressiveMesh p = simplify_progressive(in, o, keys);
  ASSERT_TRUE(p.ok) << p.message;
  ASSERT_EQ(p.first.size(), p.insertion_count() + 1);
  ASSERT_EQ(p.corners.size(), 3 * p.slots.size());
  ASSERT_EQ(p.base_corners.size(), 3 * p.base_slots.size());
  EXPECT_EQ(p.base_slots.size(), p.report.faces);
  EXPECT_GE(p.insertion_count(), p.report.removed);

  // The base is the run's output, face by face in slot order (the output's order).
  Mesh plain = in;
  Options no_slide = o;
  no_slide.slide = false;
  const std::vector<uint32_t> seams = keys ? key_seams(in, *keys) : std::vector<uint32_t>{};
  if (keys) no_slide.constrained_edges = &seams;
  const Report r = simplify(plain, no_slide);
  ASSERT_EQ(plain.face_count(), p.base_slots.size());
  std::vector<uint32_t> input_id(plain.vertex_count());
  for (size_t v = 0; v < r.remap.size(); ++v)
    if (r.remap[v] != kRemoved) input_id[r.remap[v]] = uint32_t(v);
  for (size_t f = 0; f < p.base_slots.size(); ++f)
    for (int c = 0; c < 3; ++c)
      ASSERT_EQ(in.triangles[p.base_corners[3 * f + c]], input_id[plain.triangles[3 * f + c]])
          << "base face " << f;

  const size_t worst = worst_edge(in);
  const size_t n = p.insertion_count();
  for (size_t k = 0; k <= probes; ++k) {
    const size_t count = probes ? n * k / probes : n;
    const std::string bad = check_prefix(in, apply_insertions(p, in.face_count(), count), worst);
    ASSERT_TRUE(bad.empty()) << "after " << count << " of " << n << " insertions: " << bad;
    if (!keys) continue;
    // Seams kept: each face takes its three corners from one chart (key / chart_span).
    const std::vector<uint32_t> faces = apply_insertions(p, in.face_count(), count);
    for (size_t f = 0; f < faces.size() / 3; ++f)
      if (faces[3 * f] != kEmptySlot) {
        const uint32_t chart = (*keys)[faces[3 * f]] / kChartSpan;
        ASSERT_EQ((*keys)[faces[3 * f + 1]] / kChartSpan, chart) << "slot " << f << " spans charts";
        ASSERT_EQ((*keys)[faces[3 * f + 2]] / kChartSpan, chart) << "slot " << f << " spans charts";
      }
  }
  // Whole: each kept input face back in its own slot, its corners the input's, its
  // orientation the input's unless the run reported faces reoriented.
  const std::vector<uint32_t> all = apply_insertions(p, in.face_count(), n);
  size_t empty = 0, turned = 0;
  for (size_t s = 0; s < in.face_count(); ++s) {
    if (all[3 * s] == kEmptySlot) {
      ++empty;
      continue;
    }
    const uint32_t own[3] = {uint32_t(3 * s), uint32_t(3 * s + 1), uint32_t(3 * s + 2)};
    const uint32_t back[3] = {uint32_t(3 * s), uint32_t(3 * s + 2), uint32_t(3 * s + 1)};
    const auto got = rotated(&all[3 * s]);
    if (got == rotated(back) && got != rotated(own)) {
      ++turned;
      continue;
    }
    ASSERT_EQ(got, rotated(own)) << "slot " << s;
  }
  EXPECT_EQ(empty, p.report.dropped_degenerate_faces);
  EXPECT_LE(turned, p.report.reoriented_faces);
}

Options at(double ratio) {
  Options o;
  o.target.kind = TargetKind::Ratio;
  o.target.ratio = ratio;
  return o;
}

} // namespace

TEST(Progressive, EveryPrefixValidAndTheWholeIsTheInputOnRealMeshes) {
  for (const auto& [name, mesh] : vrs_test::comparison_meshes())
    for (double ratio : {0.1, 0.01})
      check_progressive(name + " " + std::to_string(ratio), mesh, at(ratio));
}

TEST(Progressive, SmallMeshEveryPrefix) {
  const Mesh grid = vrs_test::grid(12, 0.2f);
  const ProgressiveMesh p = simplify_progressive(grid, at(0.05));
  ASSERT_TRUE(p.ok);
  check_progressive("grid, every prefix", grid, at(0.05), nullptr, p.insertion_count());
}

TEST(Progressive, BoundaryHolesAndCracks) {
  Options o = at(0.02);
  o.simplify_boundary = true;
  check_progressive("grid, its border simplified", vrs_test::grid(30, 0.1f), o);
  check_progressive("plate with holes", vrs_test::plate_with_holes(6, 5, {{1, 1}, {4, 3}}, 0.3f, 2),
                    at(0.05));
  check_progressive("cracked cylinder", vrs_test::cracked_cylinder(4, 6, 12), at(0.05));
}

TEST(Progressive, SeamsOfCornerKeysAndSplitVertices) {
  // A grid whose halves are two texture charts: keys differ across the middle column.
  const int side = 24;
  const Mesh grid = vrs_test::grid(side, 0.2f);
  std::vector<uint32_t> keys(grid.triangles.size());
  for (size_t f = 0; f < grid.face_count(); ++f) {
    float x = 0;
    for (int c = 0; c < 3; ++c)
      x += grid.positions[3 * grid.triangles[3 * f + c]];
    const uint32_t chart = x / 3 < grid.positions[3 * (side / 2)] ? 0 : 1;
    for (int c = 0; c < 3; ++c)
      keys[3 * f + c] = chart * kChartSpan + grid.triangles[3 * f + c];
  }
  check_progressive("grid with a seam of keys", grid, at(0.05), &keys);

  // Split vertices: the icosphere cut along a meridian into two copies of each vertex there.
  Mesh split = vrs_test::icosphere(3);
  const size_t n = split.vertex_count();
  std::map<uint32_t, uint32_t> copy;
  for (size_t i = 0; i < split.triangles.size(); i += 3) {
    float x = 0;
    for (int c = 0; c < 3; ++c)
      x += split.positions[3 * split.triangles[i + c]];
    if (x <= 0) continue; // faces on the +x side take copies of the vertices on the y = 0 cut
    for (int c = 0; c < 3; ++c) {
      const uint32_t v = split.triangles[i + c];
      if (std::abs(split.positions[3 * v + 1]) > 1e-6f) continue;
      auto [it, added] = copy.emplace(v, uint32_t(n + copy.size()));
      if (added)
        for (int k = 0; k < 3; ++k)
          split.positions.push_back(split.positions[3 * v + k]);
      split.triangles[i + c] = it->second;
    }
  }
  ASSERT_FALSE(copy.empty());
  check_progressive("icosphere with split vertices", split, at(0.05));
}

TEST(Progressive, AnyThreadCountTheSameRecord) {
  const Mesh m = vrs_test::icosphere(5);
  Options one = at(0.02), all = at(0.02);
  one.threads = 1;
  all.threads = 0;
  const ProgressiveMesh a = simplify_progressive(m, one), b = simplify_progressive(m, all);
  ASSERT_TRUE(a.ok && b.ok);
  EXPECT_EQ(a.base_slots, b.base_slots);
  EXPECT_EQ(a.base_corners, b.base_corners);
  EXPECT_EQ(a.vertex, b.vertex);
  EXPECT_EQ(a.slots, b.slots);
  EXPECT_EQ(a.corners, b.corners);
}

TEST(Progressive, BadInputIsRefused) {
  Mesh m = vrs_test::tetrahedron();
  m.triangles[0] = 99;
  const ProgressiveMesh p = simplify_progressive(m, at(0.5));
  EXPECT_FALSE(p.ok);
  EXPECT_FALSE(p.message.empty());
  const Mesh t = vrs_test::tetrahedron();
  std::vector<uint32_t> short_keys(2, 0);
  EXPECT_FALSE(simplify_progressive(t, at(0.5), &short_keys).ok);
}
