// The plugin's applyFilter called directly, as MeshLab calls it, on a MeshDocument built here:
// every failure must leave the user's layer bit for bit as it was (and no new layer behind),
// and awkward input must come out valid. The real meshlabserver and GUI tests run the same
// code from MeshLab; here the layer can be inspected after a failure, which they cannot do.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <utility>

#include "filter_plugin_2020.h"
#include "test_meshes.h"

namespace {

struct Snapshot {
  std::vector<float> pos;
  std::vector<int> faces;
  int vn = 0, fn = 0;
};

Snapshot snapshot(const CMeshO& m) {
  Snapshot s;
  s.vn = m.vn, s.fn = m.fn;
  for (const auto& v : m.vert)
    if (!v.IsD()) s.pos.insert(s.pos.end(), {v.cP()[0], v.cP()[1], v.cP()[2]});
  for (const auto& f : m.face)
    if (!f.IsD())
      for (int c = 0; c < 3; ++c)
        s.faces.push_back(int(vcg::tri::Index(m, f.cV(c))));
  return s;
}

bool same(const Snapshot& a, const Snapshot& b) {
  return a.vn == b.vn && a.fn == b.fn && a.faces == b.faces && a.pos.size() == b.pos.size() &&
         (a.pos.empty() || !std::memcmp(a.pos.data(), b.pos.data(), a.pos.size() * sizeof(float)));
}

void fill(CMeshO& cm, const vrs::Mesh& in) {
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(cm, in.vertex_count());
  for (size_t v = 0; v < in.vertex_count(); ++v, ++vi)
    vi->P() = vcg::Point3f(in.positions[3 * v], in.positions[3 * v + 1], in.positions[3 * v + 2]);
  auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(cm, in.face_count());
  for (size_t f = 0; f < in.face_count(); ++f, ++fi)
    for (int c = 0; c < 3; ++c)
      fi->V(c) = &cm.vert[in.triangles[3 * f + c]];
}

bool progress(const int, const char*) {
  return true;
}

class Direct : public ::testing::Test {
 protected:
  void SetUp() override { plugin.setLog(&log); }
  MeshModel* load(const vrs::Mesh& mesh) {
    MeshModel* m = md.addNewMesh("", "input");
    fill(m->cm, mesh);
    m->UpdateBoxAndNormals();
    return m;
  }
  bool apply(MeshModel& m, const std::function<void(RichParameterList&)>& set) {
    RichParameterList par;
    plugin.initParameterSet(nullptr, m, par);
    set(par);
    return plugin.applyFilter(nullptr, md, par, progress);
  }
  FilterVertexRemovalPlugin plugin;
  GLLogStream log;
  MeshDocument md;
};

} // namespace

TEST_F(Direct, EveryRefusalLeavesTheLayerAsItWas) {
  const std::string path = vrs_test::cgal_mesh("fandisk.off");
  if (path.empty()) GTEST_FAIL() << "fandisk.off missing: run scripts/setup.sh";
  MeshModel* m = load(vrs_test::read_off(path));
  const Snapshot before = snapshot(m->cm);
  const std::vector<std::pair<const char*, std::function<void(RichParameterList&)>>> bad = {
      {"Hash table intervals", [](auto& p) { p.setValue("Intervals", IntValue(1)); }},
      {"Percentage reduction", [](auto& p) { p.setValue("TargetPerc", FloatValue(1.5f)); }},
      {"Percentage reduction",
       [](auto& p) {
         p.setValue("TargetPerc", FloatValue(std::numeric_limits<float>::quiet_NaN()));
       }},
      {"Target number of faces", [](auto& p) { p.setValue("TargetFaceNum", IntValue(-5)); }},
      {"Target number of vertices", [](auto& p) { p.setValue("TargetVertNum", IntValue(-1)); }},
      {"Max priority", [](auto& p) { p.setValue("MaxFactor", FloatValue(-1)); }},
      {"Levels of detail", [](auto& p) { p.setValue("LODLevels", IntValue(0)); }},
      {"Unknown priority", [](auto& p) { p.setValue("Priority", EnumValue(9)); }},
      {"Unknown mesh kind", [](auto& p) { p.setValue("Mode", EnumValue(-1)); }},
      {"no face is selected", [](auto& p) { p.setValue("Selected", BoolValue(true)); }},
  };
  for (const auto& [words, set] : bad) {
    EXPECT_FALSE(apply(*m, set)) << words;
    EXPECT_TRUE(plugin.errorMsg().contains(words)) << qUtf8Printable(plugin.errorMsg());
    EXPECT_TRUE(same(snapshot(m->cm), before)) << words;
    EXPECT_EQ(md.size(), 1) << words; // no layer left behind
  }
}

TEST_F(Direct, APointCloudIsRefusedAndKept) {
  vrs::Mesh points;
  points.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  MeshModel* m = load(points);
  const Snapshot before = snapshot(m->cm);
  EXPECT_FALSE(apply(*m, [](auto&) {}));
  EXPECT_TRUE(plugin.errorMsg().contains("needs a mesh with faces"));
  EXPECT_TRUE(same(snapshot(m->cm), before));
}

TEST_F(Direct, LevelsOfDetailLeaveTheInputUntouched) {
  MeshModel* m = load(vrs_test::icosphere(4));
  const Snapshot before = snapshot(m->cm);
  ASSERT_TRUE(apply(*m, [](auto& p) {
    p.setValue("TargetFaceNum", IntValue(2560));
    p.setValue("LODLevels", IntValue(3));
  })) << qUtf8Printable(plugin.errorMsg());
  EXPECT_TRUE(same(snapshot(m->cm), before));
  ASSERT_EQ(md.size(), 4);
  int faces = m->cm.fn;
  // The levels nest: each layer's vertices are vertices of the finer one, bit for bit (what a
  // shared vertex buffer of levels of detail needs, vrsimplify --lods).
  auto positions = [](const CMeshO& cm) {
    std::set<std::array<float, 3>> out;
    for (const auto& v : cm.vert)
      if (!v.IsD()) out.insert({v.cP()[0], v.cP()[1], v.cP()[2]});
    return out;
  };
  std::set<std::array<float, 3>> finer = positions(m->cm);
  for (MeshModel* layer : md.meshList) {
    if (layer == m) continue;
    EXPECT_LT(layer->cm.fn, faces); // each level from the previous one, smaller
    faces = layer->cm.fn;
    const auto mine = positions(layer->cm);
    for (const auto& p : mine)
      ASSERT_TRUE(finer.count(p)) << "a vertex of " << qUtf8Printable(layer->label())
                                  << " is not one of the finer level's";
    finer = mine;
  }
}

TEST_F(Direct, AwkwardInputComesOutValid) {
  // NaN and huge coordinates, a repeated-corner face, a duplicate face, a non-manifold fin.
  vrs::Mesh in = vrs_test::icosphere(3);
  in.positions[0] = std::numeric_limits<float>::quiet_NaN();
  in.positions[4] = 3e37f;
  in.triangles.insert(in.triangles.end(), {5, 5, 6, 7, 8, 9, 7, 8, 9});
  in.positions.insert(in.positions.end(), {0.1f, 0.2f, 5.0f});
  const uint32_t fin = uint32_t(in.vertex_count() - 1);
  in.triangles.insert(in.triangles.end(), {in.triangles[30], in.triangles[31], fin});
  MeshModel* m = load(in);
  ASSERT_TRUE(apply(*m, [](auto& p) { p.setValue("TargetPerc", FloatValue(0.2f)); }))
      << qUtf8Printable(plugin.errorMsg());
  EXPECT_LT(m->cm.fn, int(in.face_count()));
  for (const auto& f : m->cm.face) {
    if (f.IsD()) continue;
    for (int c = 0; c < 3; ++c) {
      ASSERT_FALSE(f.cV(c)->IsD());
      ASSERT_LT(vcg::tri::Index(m->cm, f.cV(c)), m->cm.vert.size());
    }
    EXPECT_TRUE(f.cV(0) != f.cV(1) && f.cV(1) != f.cV(2) && f.cV(0) != f.cV(2));
  }
}

TEST_F(Direct, ShuffledOrientationComesOutCoherentWithItsCornerData) {
  // One face in three written the other way round, with a wedge texture coordinate naming
  // each corner's vertex: after the filter, faces kept and faces made alike walk every edge
  // opposite to their neighbour, and each corner still carries its own vertex's data.
  vrs::Mesh in = vrs_test::icosphere(3);
  for (size_t f = 0; f < in.face_count(); f += 3)
    std::swap(in.triangles[3 * f + 1], in.triangles[3 * f + 2]);
  MeshModel* m = load(in);
  m->updateDataMask(MeshModel::MM_WEDGTEXCOORD);
  for (auto& f : m->cm.face)
    for (int c = 0; c < 3; ++c)
      f.WT(c).U() = float(vcg::tri::Index(m->cm, f.V(c)));
  // Most faces survive at 80 %, a third of them reversed by the core.
  std::set<std::array<float, 3>> reversed_corners; // (first, second, third) corner's x, as given
  for (size_t f = 0; f < in.face_count(); f += 3)
    reversed_corners.insert({in.positions[3 * in.triangles[3 * f]],
                             in.positions[3 * in.triangles[3 * f + 2]],
                             in.positions[3 * in.triangles[3 * f + 1]]});
  ASSERT_TRUE(apply(*m, [](auto& p) { p.setValue("TargetPerc", FloatValue(0.8f)); }))
      << qUtf8Printable(plugin.errorMsg());
  EXPECT_LE(m->cm.fn, int(std::llround(0.8 * double(in.face_count()))));
  std::set<std::pair<const CVertexO*, const CVertexO*>> directed;
  size_t kept = 0, turned = 0;
  for (const auto& f : m->cm.face) {
    if (f.IsD()) continue;
    for (int c = 0; c < 3; ++c) {
      EXPECT_TRUE(directed.insert({f.cV(c), f.cV((c + 1) % 3)}).second) << "an edge walked twice";
      // The positions were compacted: the coordinate names the vertex's input index, whose
      // position is the input's.
      const uint32_t was = uint32_t(f.cWT(c).U());
      ASSERT_LT(was, in.vertex_count());
      EXPECT_EQ(f.cV(c)->cP()[0], in.positions[3 * was]);
      EXPECT_EQ(f.cV(c)->cP()[2], in.positions[3 * was + 2]);
    }
    ++kept;
    turned += reversed_corners.count({f.cV(0)->cP()[0], f.cV(1)->cP()[0], f.cV(2)->cP()[0]});
  }
  EXPECT_GT(kept, 0u);
  EXPECT_GT(turned, 50u) << "faces written reversed, kept and turned round";
}
