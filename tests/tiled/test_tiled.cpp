// Tiled runs: the streaming readers on every layout they take and refuse, and whole runs on a
// closed mesh cut into many tiles: watertight, input vertices only, the target, the same output
// on one worker or three, and bad input or a bad work directory as clear errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "corner_values.h"
#include "mesh_checks.h"
#include "mesh_stream.h"
#include "test_meshes.h"
#include "tile_seams.h"
#include "vrs/tiled.h"

namespace {

struct Read {
  std::vector<float> v;
  std::vector<int64_t> t;
  std::string error;
};

Read read_bytes(const std::string& bytes, const std::string& name) {
  Read r;
  std::FILE* f = fmemopen(const_cast<char*>(bytes.data()), bytes.size(), "rb");
  vrs::tiled::StreamSink sink;
  sink.vertex = [&](const double p[3]) {
    for (int a = 0; a < 3; ++a)
      r.v.push_back(float(p[a]));
  };
  sink.triangle = [&](const int64_t t[3], const vrs::tiled::CornerKeys&) {
    r.t.insert(r.t.end(), t, t + 3);
  };
  r.error = vrs::tiled::read_mesh_stream(f, name, sink);
  std::fclose(f);
  return r;
}

template <class T> std::string bytes_of(T v, bool big) {
  std::string s(sizeof v, '\0');
  std::memcpy(&s[0], &v, sizeof v);
  if (big) std::reverse(s.begin(), s.end());
  return s;
}

std::string temp_dir() {
  char tmpl[] = "/tmp/vrs_tiled_test_XXXXXX";
  return mkdtemp(tmpl);
}

void write_ply(const std::string& path, const vrs::Mesh& m) {
  std::ofstream f(path, std::ios::binary);
  f << "ply\nformat binary_little_endian 1.0\nelement vertex " << m.vertex_count()
    << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << m.face_count()
    << "\nproperty list uchar int vertex_indices\nend_header\n";
  f.write(reinterpret_cast<const char*>(m.positions.data()),
          std::streamsize(4 * m.positions.size()));
  for (size_t t = 0; t < m.face_count(); ++t) {
    const char three = 3;
    f.write(&three, 1);
    f.write(reinterpret_cast<const char*>(&m.triangles[3 * t]), 12);
  }
}

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// The binary PLY a tiled run writes (float xyz, uchar 3 + int indices).
vrs::Mesh read_output(const std::string& path) {
  const std::string data = slurp(path);
  const size_t end = data.find("end_header\n") + 11;
  unsigned long long nv = 0, nf = 0;
  std::sscanf(data.c_str() + data.find("element vertex"), "element vertex %llu", &nv);
  std::sscanf(data.c_str() + data.find("element face"), "element face %llu", &nf);
  vrs::Mesh m;
  m.positions.resize(3 * nv);
  std::memcpy(m.positions.data(), data.data() + end, 12 * nv);
  m.triangles.resize(3 * nf);
  for (size_t t = 0; t < nf; ++t)
    std::memcpy(&m.triangles[3 * t], data.data() + end + 12 * nv + 13 * t + 1, 12);
  return m;
}

std::string run(const std::string& in, const std::string& out, double ratio, uint64_t memory,
                int workers, const std::string& split_vertices = "") {
  const std::string dir = out + ".tiles";
  try {
    vrs::tiled::Settings s;
    s.split_vertices = split_vertices;
    s.ratio = ratio;
    s.faces_per_tile = vrs::tiled::faces_for_memory(memory);
    s.workdir = dir;
    vrs::tiled::Level l = vrs::tiled::begin(in, s);
    while (l.tiles) {
      vrs::tiled::run_level_locally(dir, l, workers, false);
      l = vrs::tiled::next_level(dir);
    }
    vrs::tiled::finish(dir, out);
  } catch (const std::exception& e) {
    vrs::tiled::discard(dir);
    return e.what();
  }
  vrs::tiled::discard(dir);
  return {};
}

} // namespace

TEST(StreamReaders, PlyAsciiWithPolygonsAndExtraProperties) {
  const Read r = read_bytes("ply\nformat ascii 1.0\ncomment x\nelement vertex 4\nproperty float x\n"
                            "property float y\nproperty float z\nproperty uchar red\n"
                            "element face 1\nproperty list uchar int vertex_indices\n"
                            "property float quality\nend_header\n0 0 0 1\n1 0 0 2\n1 1 0 3\n"
                            "0 1 0.5 4\n4 0 1 2 3 0.5\n",
                            "a.ply");
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.v, (std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0.5f}));
  EXPECT_EQ(r.t, (std::vector<int64_t>{0, 1, 2, 0, 2, 3}));
}

TEST(StreamReaders, PlyBinaryBothEndiannesses) {
  for (bool big : {false, true}) {
    std::string s =
        std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
        " 1.0\nelement vertex 3\nproperty double x\nproperty float y\nproperty float z\n"
        "property short flags\nelement face 1\nproperty uchar kind\n"
        "property list uchar uint vertex_index\nend_header\n";
    for (int i = 0; i < 3; ++i)
      s += bytes_of(double(i), big) + bytes_of(float(2 * i), big) + bytes_of(float(-i), big) +
           bytes_of(int16_t(7), big);
    s += std::string(1, '\x05') + std::string(1, '\x03') + bytes_of(uint32_t(2), big) +
         bytes_of(uint32_t(1), big) + bytes_of(uint32_t(0), big);
    const Read r = read_bytes(s, "b.PLY");
    ASSERT_EQ(r.error, "") << big;
    EXPECT_EQ(r.v, (std::vector<float>{0, 0, 0, 1, 2, -1, 2, 4, -2})) << big;
    EXPECT_EQ(r.t, (std::vector<int64_t>{2, 1, 0})) << big;
  }
}

TEST(StreamReaders, ObjWithCornerDataNegativeIndicesAndPolygons) {
  const Read r = read_bytes("# c\nv 0 0 0\nv 1 0 0 1 1 1\nvt 0 0\nvn 0 0 1\nv 1 1 0\nv 0 1 0\n"
                            "f 1/1/1 2/1/1 3/1/1 4/1/1\nf -1 -2 -3\n",
                            "c.obj");
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.v.size(), 12u);
  EXPECT_EQ(r.t, (std::vector<int64_t>{0, 1, 2, 0, 2, 3, 3, 2, 1}));
}

TEST(StreamReaders, MalformedFilesSayWhat) {
  const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 2\n"
                             "property float x\nproperty float y\nproperty float z\nend_header\n";
  EXPECT_NE(read_bytes(header + std::string(13, '\0'), "t.ply").error.find("truncated"),
            std::string::npos);
  EXPECT_NE(
      read_bytes("ply\nformat ascii 1.0\nelement vertex\n", "h.ply").error.find("bad PLY element"),
      std::string::npos);
  EXPECT_NE(read_bytes("ply\nformat binary_middle 1.0\nend_header\n", "f.ply")
                .error.find("unknown PLY format"),
            std::string::npos);
  EXPECT_NE(read_bytes("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n",
                       "x.ply")
                .error.find("without x, y and z"),
            std::string::npos);
  EXPECT_NE(read_bytes("solid", "s.ply").error.find("not a PLY"), std::string::npos);
  EXPECT_NE(read_bytes("v 1 2\n", "v.obj").error.find("line 1: bad vertex"), std::string::npos);
  EXPECT_NE(read_bytes("v 0 0 0\nf 1 2\n", "f.obj").error.find("fewer than 3"), std::string::npos);
  EXPECT_NE(read_bytes("", "x.stl").error.find(".ply, .obj or .off"), std::string::npos);
  EXPECT_NE(read_bytes("OFF\n3 1 0\n0 0 0\n1 0 0\n", "t.off").error.find("truncated"),
            std::string::npos);
}

TEST(Tiled, ClosedMeshInManyTilesStaysWatertightAndKeepsInputVertices) {
  const std::string dir = temp_dir();
  const vrs::Mesh in = vrs_test::icosphere(6); // 81 920 faces
  write_ply(dir + "/in.ply", in);
  // 1.6 MB: tiles of 2 000 faces, dozens of them at level 1.
  ASSERT_EQ(run(dir + "/in.ply", dir + "/one.ply", 0.05, 1600000, 1), "");
  ASSERT_EQ(run(dir + "/in.ply", dir + "/three.ply", 0.05, 1600000, 3), "");
  EXPECT_EQ(slurp(dir + "/one.ply"), slurp(dir + "/three.ply")); // whoever ran the tiles
  const vrs::Mesh out = read_output(dir + "/one.ply");
  EXPECT_LE(out.face_count(), size_t(0.05 * 81920 * 1.005 + 2));
  EXPECT_GE(out.face_count(), size_t(0.05 * 81920 * 0.9));
  std::set<std::vector<float>> inputs;
  for (size_t v = 0; v < in.vertex_count(); ++v)
    inputs.insert({in.positions[3 * v], in.positions[3 * v + 1], in.positions[3 * v + 2]});
  for (size_t v = 0; v < out.vertex_count(); ++v)
    EXPECT_TRUE(
        inputs.count({out.positions[3 * v], out.positions[3 * v + 1], out.positions[3 * v + 2]}));
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (size_t t = 0; t < out.face_count(); ++t)
    for (int c = 0; c < 3; ++c)
      ++directed[{out.triangles[3 * t + c], out.triangles[3 * t + (c + 1) % 3]}];
  for (const auto& [e, n] : directed) { // every edge once each way: closed, manifold, oriented
    EXPECT_EQ(n, 1);
    EXPECT_EQ(directed.count({e.second, e.first}), 1u);
  }
  vrs::tiled::discard(dir);
}

// A sphere whose upper faces hold their own copies of the equator's vertices (a seam written
// as split vertices, positions only): every tile welds the copies it holds, as the in-core run
// does (the default for a file of positions only, and "weld"), so the equator is simplified
// with the rest and the output closes by position, every corner on an input vertex, faces
// crossing the equator where it went; "seam" keeps it as a polyline (simplified along itself,
// no face across it); "keep" leaves the copies apart as borders (it stays whole); a bad name
// is refused.
// A sphere of 20 480 faces whose upper half has its own copies of the equator's vertices.
struct SplitSphere {
  vrs::Mesh whole = vrs_test::icosphere(5), in;
  std::vector<uint8_t> used; // per vertex of `whole`: 1 used by lower faces, 2 by upper, 3 both
  size_t equator = 0;
  bool upper(size_t f) const {
    float z = 0;
    for (int c = 0; c < 3; ++c)
      z += whole.positions[3 * whole.triangles[3 * f + c] + 2];
    return z > 0;
  }
  // `lower_turned`: the lower half written in the other orientation (a CAD export's panels).
  explicit SplitSphere(bool lower_turned) : in(whole), used(whole.vertex_count(), 0) {
    for (size_t f = 0; f < whole.face_count(); ++f)
      for (int c = 0; c < 3; ++c)
        used[whole.triangles[3 * f + c]] |= upper(f) ? 2 : 1;
    std::vector<uint32_t> copy(whole.vertex_count(), vrs::kRemoved);
    for (uint32_t v = 0; v < whole.vertex_count(); ++v)
      if (used[v] == 3) {
        copy[v] = uint32_t(in.vertex_count());
        in.positions.insert(in.positions.end(), &whole.positions[3 * v],
                            &whole.positions[3 * v] + 3);
        ++equator;
      }
    for (size_t f = 0; f < whole.face_count(); ++f) {
      uint32_t* t = &in.triangles[3 * f];
      for (int c = 0; c < 3 && upper(f); ++c)
        if (copy[t[c]] != vrs::kRemoved) t[c] = copy[t[c]];
      if (lower_turned && !upper(f)) std::swap(t[1], t[2]);
    }
  }
};

TEST(Tiled, SplitVerticesAreWeldedTileByTile) {
  const std::string dir = temp_dir();
  const SplitSphere sphere(false);
  const vrs::Mesh &whole = sphere.whole, &in = sphere.in;
  const auto& used = sphere.used;
  const size_t equator = sphere.equator;
  ASSERT_GT(equator, 100u);
  write_ply(dir + "/in.ply", in);
  std::set<std::array<float, 3>> inputs, on_equator;
  for (size_t v = 0; v < in.vertex_count(); ++v)
    inputs.insert({in.positions[3 * v], in.positions[3 * v + 1], in.positions[3 * v + 2]});
  for (uint32_t v = 0; v < whole.vertex_count(); ++v)
    if (used[v] == 3)
      on_equator.insert(
          {whole.positions[3 * v], whole.positions[3 * v + 1], whole.positions[3 * v + 2]});
  // Output positions on the equator, and edges by their end positions (closed: each twice).
  auto equator_kept = [&](const vrs::Mesh& out) {
    std::set<std::array<float, 3>> kept;
    for (size_t v = 0; v < out.vertex_count(); ++v) {
      const std::array<float, 3> p{out.positions[3 * v], out.positions[3 * v + 1],
                                   out.positions[3 * v + 2]};
      EXPECT_TRUE(inputs.count(p)) << "output vertex " << v << " is no input vertex";
      if (on_equator.count(p)) kept.insert(p);
    }
    return kept.size();
  };
  auto open_edges = [](const vrs::Mesh& out) {
    size_t open = 0;
    for (const auto& [e, n] : vrs_test::edges_by_position(out))
      open += n != 2;
    return open;
  };
  // Faces with a corner only the upper faces used and one only the lower ones did.
  std::map<std::array<float, 3>, uint8_t> side;
  for (uint32_t v = 0; v < whole.vertex_count(); ++v)
    side[{whole.positions[3 * v], whole.positions[3 * v + 1], whole.positions[3 * v + 2]}] =
        used[v];
  auto across = [&](const vrs::Mesh& out) {
    size_t n = 0;
    for (size_t f = 0; f < out.face_count(); ++f) {
      uint8_t sides = 0;
      for (int c = 0; c < 3; ++c) {
        const float* p = &out.positions[3 * out.triangles[3 * f + c]];
        const uint8_t u = side[{p[0], p[1], p[2]}];
        sides |= u == 3 ? 0 : u;
      }
      n += sides == 3;
    }
    return n;
  };
  for (const std::string split : {"", "weld"}) {
    SCOPED_TRACE("split_vertices \"" + split + "\"");
    // 1.6 MB: tiles of 2 000 faces, a dozen at level 1.
    ASSERT_EQ(run(dir + "/in.ply", dir + "/out.ply", 0.05, 1600000, 2, split), "");
    const vrs::Mesh out = read_output(dir + "/out.ply");
    EXPECT_LE(out.face_count(), size_t(0.05 * 20480 * 1.005 + 2));
    EXPECT_EQ(open_edges(out), 0u); // no crack along the seam
    EXPECT_LT(equator_kept(out), equator / 2);
    EXPECT_GT(across(out), 0u);
  }
  ASSERT_EQ(run(dir + "/in.ply", dir + "/seam.ply", 0.05, 1600000, 2, "seam"), "");
  const vrs::Mesh seam = read_output(dir + "/seam.ply");
  EXPECT_EQ(open_edges(seam), 0u);
  EXPECT_LT(equator_kept(seam), equator / 2);
  EXPECT_EQ(across(seam), 0u);
  ASSERT_EQ(run(dir + "/in.ply", dir + "/kept.ply", 0.05, 1600000, 2, "keep"), "");
  const vrs::Mesh kept = read_output(dir + "/kept.ply");
  EXPECT_EQ(equator_kept(kept), equator);
  EXPECT_EQ(open_edges(kept), 0u);
  EXPECT_NE(run(dir + "/in.ply", dir + "/never.ply", 0.05, 1600000, 2, "glue")
                .find("split_vertices must be seam, weld or keep"),
            std::string::npos);
  vrs::tiled::discard(dir);
}

TEST(Tiled, PiecesWrittenInOtherOrientationsKeepTheirOwn) {
  // As in core: the lower half's faces written turned over, its seam split, are welded to the
  // upper half tile by tile, simplified along the seam, and written each as its input was.
  const std::string dir = temp_dir();
  const SplitSphere sphere(true);
  write_ply(dir + "/in.ply", sphere.in);
  ASSERT_EQ(run(dir + "/in.ply", dir + "/out.ply", 0.05, 1600000, 2, "weld"), "");
  const vrs::Mesh out = read_output(dir + "/out.ply");
  EXPECT_LE(out.face_count(), size_t(0.05 * 20480 * 1.005 + 2));
  std::map<std::array<float, 3>, uint8_t> side;
  for (uint32_t v = 0; v < sphere.whole.vertex_count(); ++v)
    side[{sphere.whole.positions[3 * v], sphere.whole.positions[3 * v + 1],
          sphere.whole.positions[3 * v + 2]}] = sphere.used[v];
  std::set<std::array<float, 3>> on_equator; // positions: each is written twice
  for (size_t v = 0; v < out.vertex_count(); ++v) {
    const std::array<float, 3> x{out.positions[3 * v], out.positions[3 * v + 1],
                                 out.positions[3 * v + 2]};
    if (side[x] == 3) on_equator.insert(x);
  }
  size_t judged = 0;
  EXPECT_LT(on_equator.size(), sphere.equator / 2) << "the seam simplified along itself";
  for (size_t f = 0; f < out.face_count(); ++f) {
    uint8_t sides = 0;
    const float* p[3];
    for (int c = 0; c < 3; ++c) {
      const float* x = p[c] = &out.positions[3 * out.triangles[3 * f + c]];
      const uint8_t u = side[{x[0], x[1], x[2]}];
      sides |= u == 3 ? 0 : u;
    }
    ASSERT_NE(sides, 3) << "face " << f << " spans the seam";
    if (!sides) continue; // all three on the seam
    ++judged;
    double e1[3], e2[3], sum[3];
    for (int k = 0; k < 3; ++k)
      e1[k] = p[1][k] - p[0][k], e2[k] = p[2][k] - p[0][k], sum[k] = p[0][k] + p[1][k] + p[2][k];
    const double normal[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                              e1[0] * e2[1] - e1[1] * e2[0]};
    const bool outward = normal[0] * sum[0] + normal[1] * sum[1] + normal[2] * sum[2] > 0;
    EXPECT_EQ(outward, sides == 2) << "face " << f << " turned against its input";
  }
  EXPECT_GT(judged, out.face_count() / 2);
  for (const auto& [e, n] : vrs_test::edges_by_position(out))
    ASSERT_EQ(n, 2) << "a crack along the seam";
  vrs::tiled::discard(dir);
}

// A noisy height field cut into tiles of 1 310 faces: where the octree's small leaves stall
// against their locked borders, the next level's tiles are halves of up to a lone tile's
// budget (one at a time), and the run reaches its target as in core (it stalled at 4 times
// the target).
TEST(Tiled, SmallTilesThatStallGrowAndReachTheTarget) {
  const std::string dir = temp_dir();
  vrs::Mesh m = vrs_test::grid(119); // 120 x 120 vertices
  uint32_t seed = 7;
  for (size_t v = 0; v < m.vertex_count(); ++v) { // hills and noise: nothing is flat
    seed = seed * 1664525u + 1013904223u;
    const float x = m.positions[3 * v], y = m.positions[3 * v + 1];
    m.positions[3 * v] = 0.5f * x, m.positions[3 * v + 1] = 0.5f * y;
    m.positions[3 * v + 2] =
        3.0f * std::sin(x / 9.0f) * std::cos(y / 7.0f) + 0.01f * float(seed >> 8) / float(1u << 24);
  }
  write_ply(dir + "/in.ply", m);
  for (double ratio : {0.1, 0.01}) {
    // --memory 1M, as the CLI reads it (tiles of 1 310 faces).
    ASSERT_EQ(run(dir + "/in.ply", dir + "/out.ply", ratio, 1 << 20, 2), "");
    const vrs::Mesh out = read_output(dir + "/out.ply");
    EXPECT_LE(out.face_count(), size_t(ratio * double(m.face_count()) * 1.005 + 2)) << ratio;
  }
  vrs::tiled::discard(dir);
}

TEST(Tiled, BadInputAndWorkDirectoriesAreClearErrorsAndLeaveNothing) {
  const std::string dir = temp_dir();
  std::ofstream(dir + "/range.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n";
  EXPECT_NE(run(dir + "/range.obj", dir + "/o.ply", 0.5, 1 << 30, 1).find("out of range"),
            std::string::npos);
  std::ofstream(dir + "/nan.obj")
      << "v 0 0 0\nv 1 0 0\nv nan 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n";
  EXPECT_EQ(run(dir + "/nan.obj", dir + "/nan.obj.out.obj", 0.5, 1 << 30, 1), ""); // kept, valid
  EXPECT_NE(run(dir + "/missing.ply", dir + "/o.ply", 0.5, 1 << 30, 1).find("cannot read"),
            std::string::npos);
  std::ofstream(dir + "/file") << "x";
  vrs::tiled::Settings s;
  s.workdir = dir + "/file/sub";
  EXPECT_THROW(vrs::tiled::begin(dir + "/nan.obj", s), std::runtime_error);
  s.workdir = dir + "/w";
  s.ratio = 2;
  EXPECT_THROW(vrs::tiled::begin(dir + "/nan.obj", s), std::runtime_error);
  std::ifstream o(dir + "/o.ply");
  EXPECT_FALSE(o.good()); // no output of a failed run
  EXPECT_THROW(vrs::tiled::make_work_dir(dir + "/file"), std::runtime_error);
  vrs::tiled::discard(dir);
}

TEST(Tiled, AWorkDirectoryIsAFreshFolderInTheOneNamedAndOnlyItIsRemoved) {
  const std::string dir = temp_dir();
  std::ofstream(dir + "/yours.txt") << "keep me";
  const std::string a = vrs::tiled::make_work_dir(dir), b = vrs::tiled::make_work_dir(dir);
  EXPECT_NE(a, b);
  EXPECT_EQ(a.rfind(dir + "/vrsimplify-tiles-", 0), 0u);
  vrs::tiled::discard(a);
  vrs::tiled::discard(b);
  std::ifstream kept(dir + "/yours.txt");
  std::string text;
  std::getline(kept, text);
  EXPECT_EQ(text, "keep me");
  const std::string made = vrs::tiled::make_work_dir(dir + "/new"); // a missing parent is made
  EXPECT_EQ(made.rfind(dir + "/new/vrsimplify-tiles-", 0), 0u);
  vrs::tiled::discard(dir);
}

namespace {

// The lines of a text file from the first that starts with `from`.
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    out.push_back(line);
  return out;
}

// A mesh's OBJ v lines, 9 digits (what the float holds).
std::string obj_v_lines(const vrs::Mesh& m) {
  std::string out;
  char line[96];
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", double(m.positions[3 * v]),
                  double(m.positions[3 * v + 1]), double(m.positions[3 * v + 2]));
    out += line;
  }
  return out;
}

// A tiled run's faces for `ratio` of `input` faces: at the target within its half per cent.
void expect_at_target(size_t faces, size_t input, double ratio) {
  EXPECT_LE(faces, size_t(ratio * double(input) * 1.005 + 2));
  EXPECT_GE(faces, size_t(ratio * double(input) * 0.9));
}

// A PLY's header lines and the bytes after it.
std::pair<std::vector<std::string>, std::string> ply_parts(const std::string& data) {
  const size_t end = data.find("end_header\n") + 11;
  return {lines_of(data.substr(0, end)), data.substr(end)};
}

} // namespace

// Every property of every vertex passes bit for bit, in the input's own encoding: double
// coordinates stay double, colors, normals and quality stay, whatever the byte order.
TEST(Tiled, EveryVertexPropertyPassesBitForBitInEveryEncoding) {
  const std::string dir = temp_dir();
  const vrs::Mesh m = vrs_test::icosphere(5); // 20 480 faces
  for (const char* format : {"binary_little_endian", "binary_big_endian", "ascii"}) {
    const bool ascii = std::string(format) == "ascii",
               big = std::string(format) == "binary_big_endian";
    std::string data = std::string("ply\nformat ") + format + " 1.0\nelement vertex " +
                       std::to_string(m.vertex_count()) +
                       "\nproperty double x\nproperty double y\nproperty double z\n"
                       "property float nx\nproperty float ny\nproperty float nz\n"
                       "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                       "property float quality\nelement face " +
                       std::to_string(m.face_count()) +
                       "\nproperty list uchar int vertex_indices\nend_header\n";
    std::vector<std::string> records; // each vertex as written
    for (size_t v = 0; v < m.vertex_count(); ++v) {
      // Coordinates a float cannot hold (a survey's magnitudes with sub-millimetre digits).
      const double xyz[3] = {500000.123456789 + m.positions[3 * v],
                             4100000.987654321 + m.positions[3 * v + 1],
                             m.positions[3 * v + 2] + 1e-9 * double(v)};
      const uint8_t rgb[3] = {uint8_t(v), uint8_t(v * 7), uint8_t(v * 13)};
      std::string r;
      if (ascii) {
        char b[256];
        std::snprintf(b, sizeof b, "%.17g %.17g %.17g %.9g %.9g %.9g %u %u %u %.9g", xyz[0], xyz[1],
                      xyz[2], double(m.positions[3 * v]), double(m.positions[3 * v + 1]),
                      double(m.positions[3 * v + 2]), rgb[0], rgb[1], rgb[2], 0.25 * double(v));
        r = b;
        data += r + "\n";
      } else {
        for (double c : xyz)
          r += bytes_of(c, big);
        for (int a = 0; a < 3; ++a)
          r += bytes_of(m.positions[3 * v + a], big);
        r += std::string(reinterpret_cast<const char*>(rgb), 3) +
             bytes_of(float(0.25 * double(v)), big);
        data += r;
      }
      records.push_back(r);
    }
    for (size_t t = 0; t < m.face_count(); ++t) {
      if (ascii) {
        data += "3 " + std::to_string(m.triangles[3 * t]) + " " +
                std::to_string(m.triangles[3 * t + 1]) + " " +
                std::to_string(m.triangles[3 * t + 2]) + "\n";
        continue;
      }
      data += '\x03';
      for (int c = 0; c < 3; ++c)
        data += bytes_of(int32_t(m.triangles[3 * t + c]), big);
    }
    std::ofstream(dir + "/in.ply", std::ios::binary) << data;
    ASSERT_EQ(run(dir + "/in.ply", dir + "/out.ply", 0.1, 1000000, 2), "") << format; // many tiles
    const auto [in_header, in_body] = ply_parts(data);
    const auto [out_header, out_body] = ply_parts(slurp(dir + "/out.ply"));
    // The same vertex element, the counts aside.
    std::vector<std::string> in_props, out_props;
    for (const std::string& l : in_header)
      if (l.rfind("property", 0) == 0 || l.rfind("format", 0) == 0) in_props.push_back(l);
    for (const std::string& l : out_header)
      if (l.rfind("property", 0) == 0 || l.rfind("format", 0) == 0) out_props.push_back(l);
    EXPECT_EQ(in_props, out_props) << format;
    unsigned long long nv = 0, nf = 0;
    for (const std::string& l : out_header) {
      std::sscanf(l.c_str(), "element vertex %llu", &nv);
      std::sscanf(l.c_str(), "element face %llu", &nf);
    }
    EXPECT_LE(nf, size_t(0.1 * double(m.face_count()) * 1.005 + 2)) << format;
    EXPECT_GE(nf, size_t(0.1 * double(m.face_count()) * 0.9)) << format;
    const std::set<std::string> inputs(records.begin(), records.end());
    size_t exact = 0;
    if (ascii) {
      const std::vector<std::string> lines = lines_of(out_body);
      ASSERT_EQ(lines.size(), nv + nf) << format;
      for (size_t v = 0; v < nv; ++v)
        exact += inputs.count(lines[v]);
    } else {
      ASSERT_EQ(out_body.size(), nv * 43 + nf * 13) << format;
      for (size_t v = 0; v < nv; ++v)
        exact += inputs.count(out_body.substr(43 * v, 43));
    }
    EXPECT_EQ(exact, nv) << format << ": every output vertex is an input vertex, every bit";
  }
  vrs::tiled::discard(dir);
}

// Per-corner data stays with its chart: each output corner is an input corner (its v, vt and
// vn lines and its material), seams kept inside tiles as in core; the material library is
// named from the output's folder.
TEST(Tiled, CornerDataAndMaterialsStayWithTheirChart) {
  const std::string dir = temp_dir();
  const vrs::Mesh m = vrs_test::icosphere(5);
  std::ostringstream obj;
  obj << "mtllib in.mtl\n";
  for (size_t v = 0; v < m.vertex_count(); ++v)
    obj << "v " << m.positions[3 * v] << " " << m.positions[3 * v + 1] << " "
        << m.positions[3 * v + 2] << "\nvn " << m.positions[3 * v] << " " << m.positions[3 * v + 1]
        << " " << m.positions[3 * v + 2] << "\n";
  // Four charts by the sign of the centroid's x and y, two materials by the sign of x; one vt
  // per (vertex, chart), its value naming both.
  std::map<std::pair<uint32_t, int>, size_t> vt;
  std::vector<int> chart(m.face_count());
  for (size_t t = 0; t < m.face_count(); ++t) {
    float cx = 0, cy = 0;
    for (int c = 0; c < 3; ++c)
      cx += m.positions[3 * m.triangles[3 * t + c]],
          cy += m.positions[3 * m.triangles[3 * t + c] + 1];
    chart[t] = (cx > 0) * 2 + (cy > 0);
    for (int c = 0; c < 3; ++c) {
      const uint32_t v = m.triangles[3 * t + c];
      if (vt.emplace(std::make_pair(v, chart[t]), vt.size() + 1).second)
        obj << "vt " << v << " " << chart[t] << "\n";
    }
  }
  std::set<std::vector<std::string>> corners; // (v line, vt line, vn line, material)
  std::vector<std::string> vlines, vnlines, vtlines(vt.size() + 1);
  for (const auto& [key, i] : vt)
    vtlines[i] = "vt " + std::to_string(key.first) + " " + std::to_string(key.second);
  for (int mat : {0, 1}) {
    obj << "usemtl side" << mat << "\n";
    for (size_t t = 0; t < m.face_count(); ++t) {
      if (chart[t] / 2 != mat) continue;
      obj << "f";
      for (int c = 0; c < 3; ++c) {
        const uint32_t v = m.triangles[3 * t + c];
        obj << " " << v + 1 << "/" << vt[{v, chart[t]}] << "/" << v + 1;
        corners.insert({std::to_string(v), vtlines[vt[{v, chart[t]}]], std::to_string(v),
                        "side" + std::to_string(mat)});
      }
      obj << "\n";
    }
  }
  std::ofstream(dir + "/in.obj") << obj.str();
  ASSERT_EQ(system(("mkdir -p " + dir + "/sub").c_str()), 0);
  ASSERT_EQ(run(dir + "/in.obj", dir + "/sub/out.obj", 0.1, 1000000, 2), "");
  // Read the output back: its v/vt/vn lines by index, faces by material.
  std::vector<std::string> ov, ovt, ovn;
  std::string material, library;
  size_t faces = 0, wrong = 0;
  std::map<std::string, size_t> input_v; // a v line -> input vertex
  {
    std::istringstream in(obj.str());
    size_t k = 0;
    for (std::string l; std::getline(in, l);)
      if (l.rfind("v ", 0) == 0) input_v[l] = k++;
  }
  for (const std::string& l : lines_of(slurp(dir + "/sub/out.obj"))) {
    if (l.rfind("v ", 0) == 0) ov.push_back(std::to_string(input_v.count(l) ? input_v[l] : 999999));
    if (l.rfind("vt ", 0) == 0) ovt.push_back(l);
    if (l.rfind("vn ", 0) == 0) ovn.push_back(l);
    if (l.rfind("usemtl ", 0) == 0) material = l.substr(7);
    if (l.rfind("mtllib ", 0) == 0) library = l.substr(7);
    if (l.rfind("f ", 0) != 0) continue;
    ++faces;
    unsigned a[3], b[3], c[3];
    ASSERT_EQ(std::sscanf(l.c_str(), "f %u/%u/%u %u/%u/%u %u/%u/%u", &a[0], &b[0], &c[0], &a[1],
                          &b[1], &c[1], &a[2], &b[2], &c[2]),
              9)
        << l;
    for (int k = 0; k < 3; ++k) {
      ASSERT_TRUE(a[k] >= 1 && a[k] <= ov.size() && b[k] >= 1 && b[k] <= ovt.size() && c[k] >= 1 &&
                  c[k] <= ovn.size());
      // vn lines are the vertex's own normal: the same vertex's v line index.
      const std::string v = ov[a[k] - 1];
      wrong += !corners.count({v, ovt[b[k] - 1], v, material});
    }
  }
  EXPECT_EQ(library, "../in.mtl");
  expect_at_target(faces, m.face_count(), 0.1);
  EXPECT_EQ(wrong, 0u) << "output corners that are no input corner (v, vt, vn, material)";
  vrs::tiled::discard(dir);
}

// Flat shading (every face's corners name one vn line, its own normal) holds nothing the
// geometry does not, as in core: no edge is a seam, the tiles are those of the mesh without
// normals (the same output faces), and each output face is given its own unit normal. (Taken
// as per-corner keys, every edge had been a seam and nothing was removed: 12 946 -> 12 946.)
TEST(Tiled, FlatShadedObjIsSimplifiedAsWithoutNormalsAndFacesGetTheirOwn) {
  const std::string dir = temp_dir();
  const vrs::Mesh m = vrs_test::icosphere(5);
  std::ostringstream plain, flat;
  plain << obj_v_lines(m);
  flat << obj_v_lines(m);
  auto at = [](const float* p) { return std::array<double, 3>{p[0], p[1], p[2]}; };
  auto unit_normal = [](std::array<double, 3> a, std::array<double, 3> b, std::array<double, 3> c) {
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                 w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    std::array<double, 3> n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                            u[0] * w[1] - u[1] * w[0]};
    const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n)
      x /= l;
    return n;
  };
  for (size_t t = 0; t < m.face_count(); ++t) {
    const uint32_t* f = &m.triangles[3 * t];
    const auto n = unit_normal(at(&m.positions[3 * f[0]]), at(&m.positions[3 * f[1]]),
                               at(&m.positions[3 * f[2]]));
    flat << "vn " << n[0] << " " << n[1] << " " << n[2] << "\n";
    plain << "f " << f[0] + 1 << " " << f[1] + 1 << " " << f[2] + 1 << "\n";
    flat << "f " << f[0] + 1 << "//" << t + 1 << " " << f[1] + 1 << "//" << t + 1 << " " << f[2] + 1
         << "//" << t + 1 << "\n";
  }
  std::ofstream(dir + "/plain.obj") << plain.str();
  std::ofstream(dir + "/flat.obj") << flat.str();
  ASSERT_EQ(run(dir + "/plain.obj", dir + "/plain_out.obj", 0.1, 1000000, 2), "");
  ASSERT_EQ(run(dir + "/flat.obj", dir + "/flat_out.obj", 0.1, 1000000, 2), "");
  std::vector<std::string> plain_lines, flat_lines; // v and f lines, normals left out
  std::vector<std::array<double, 3>> v, vn;
  size_t faces = 0, wrong = 0;
  for (const std::string& l : lines_of(slurp(dir + "/plain_out.obj")))
    if (l.rfind("v ", 0) == 0 || l.rfind("f ", 0) == 0) plain_lines.push_back(l);
  for (const std::string& l : lines_of(slurp(dir + "/flat_out.obj"))) {
    std::array<double, 3> x;
    if (l.rfind("v ", 0) == 0 || l.rfind("vn ", 0) == 0) {
      ASSERT_EQ(std::sscanf(l.c_str() + l.find(' '), "%lf %lf %lf", &x[0], &x[1], &x[2]), 3) << l;
      (l[1] == 'n' ? vn : v).push_back(x);
    }
    if (l.rfind("v ", 0) == 0) flat_lines.push_back(l);
    if (l.rfind("f ", 0) != 0) continue;
    unsigned a[3], n[3];
    ASSERT_EQ(
        std::sscanf(l.c_str(), "f %u//%u %u//%u %u//%u", &a[0], &n[0], &a[1], &n[1], &a[2], &n[2]),
        6)
        << l;
    flat_lines.push_back("f " + std::to_string(a[0]) + " " + std::to_string(a[1]) + " " +
                         std::to_string(a[2]));
    ++faces;
    ASSERT_TRUE(n[0] == n[1] && n[1] == n[2] && n[0] >= 1 && n[0] <= vn.size()) << l;
    ASSERT_TRUE(a[0] <= v.size() && a[1] <= v.size() && a[2] <= v.size()) << l;
    const auto own = unit_normal(v[a[0] - 1], v[a[1] - 1], v[a[2] - 1]);
    const auto& given = vn[n[0] - 1];
    wrong += !(own[0] * given[0] + own[1] * given[1] + own[2] * given[2] > 1 - 1e-5);
  }
  EXPECT_EQ(flat_lines, plain_lines) << "flat normals changed which vertices and faces are kept";
  expect_at_target(faces, m.face_count(), 0.1);
  EXPECT_EQ(wrong, 0u) << "output faces whose normal is not their own";
  vrs::tiled::discard(dir);
}

// Corners agree by the values their vt and vn lines hold, as in core, not by which line they
// name: an unindexed file (every corner its own lines) has no seam where the values agree; a
// normal turning more than 60 degrees, or another texture coordinate, still makes one.
TEST(Tiled, CornersAgreeByValueNotByLine) {
  const std::string dir = temp_dir();
  // Two triangles on the edge (1, 2), each corner naming its own vt and vn line.
  vrs::Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  m.triangles = {0, 1, 2, 2, 1, 3};
  auto seams_with = [&](std::vector<float> vt, std::vector<float> vn) {
    for (const auto& [name, values] : {std::make_pair("vt.bin", vt), std::make_pair("vn.bin", vn)})
      std::ofstream(dir + "/" + name, std::ios::binary)
          .write(reinterpret_cast<const char*>(values.data()), std::streamsize(4 * values.size()));
    const vrs::tiled::CornerValues t(dir + "/vt.bin", 2), n(dir + "/vn.bin", 3);
    vrs::tiled::TileKeys keys;
    keys.a = keys.b = {1, 2, 3, 4, 5, 6}; // corner k of face f names line 3 f + k + 1
    keys.group = {0, 0};
    keys.texcoords = &t, keys.normals = &n;
    return vrs::tiled::tile_seams(m, keys).size() / 2;
  };
  // Lines 2, 3 (face 0's corners at vertices 1, 2) and 5, 4 (face 1's at 1, 2) are the edge's.
  const std::vector<float> uv = {0, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1, 1};
  const std::vector<float> up = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  EXPECT_EQ(seams_with(uv, up), 0u) << "the same values on other lines";
  std::vector<float> tilted = up;
  tilted[3 * 4 + 0] = 0.5f; // line 5: 27 degrees from line 2's, smooth shading
  EXPECT_EQ(seams_with(uv, tilted), 0u) << "normals within the crease angle";
  tilted[3 * 4 + 0] = 1, tilted[3 * 4 + 2] = 0; // 90 degrees: a hard edge
  EXPECT_EQ(seams_with(uv, tilted), 1u) << "a hard edge";
  std::vector<float> moved = uv;
  moved[2 * 3 + 1] = 0.5f; // line 4 (vertex 2 in face 1) another texture coordinate
  EXPECT_EQ(seams_with(moved, up), 1u) << "a texture seam";

  // A whole run: a sphere's vertex normals written on a line per corner simplifies as the
  // same sphere without normals (12 946 -> 12 946 faces before, every edge a seam).
  const vrs::Mesh s = vrs_test::icosphere(5);
  std::ostringstream plain, unindexed;
  plain << obj_v_lines(s);
  unindexed << obj_v_lines(s);
  for (size_t t = 0; t < s.face_count(); ++t) {
    const uint32_t* f = &s.triangles[3 * t];
    for (int c = 0; c < 3; ++c)
      unindexed << "vn " << s.positions[3 * f[c]] << " " << s.positions[3 * f[c] + 1] << " "
                << s.positions[3 * f[c] + 2] << "\n";
    plain << "f " << f[0] + 1 << " " << f[1] + 1 << " " << f[2] + 1 << "\n";
    unindexed << "f " << f[0] + 1 << "//" << 3 * t + 1 << " " << f[1] + 1 << "//" << 3 * t + 2
              << " " << f[2] + 1 << "//" << 3 * t + 3 << "\n";
  }
  std::ofstream(dir + "/plain.obj") << plain.str();
  std::ofstream(dir + "/unindexed.obj") << unindexed.str();
  ASSERT_EQ(run(dir + "/plain.obj", dir + "/plain_out.obj", 0.1, 1000000, 2), "");
  ASSERT_EQ(run(dir + "/unindexed.obj", dir + "/unindexed_out.obj", 0.1, 1000000, 2), "");
  size_t faces = 0, plain_faces = 0;
  for (const std::string& l : lines_of(slurp(dir + "/plain_out.obj")))
    plain_faces += l.rfind("f ", 0) == 0;
  std::vector<std::string> v, vn;
  size_t wrong = 0;
  for (const std::string& l : lines_of(slurp(dir + "/unindexed_out.obj"))) {
    if (l.rfind("v ", 0) == 0) v.push_back(l.substr(2));
    if (l.rfind("vn ", 0) == 0) vn.push_back(l.substr(3));
    if (l.rfind("f ", 0) != 0) continue;
    ++faces;
    unsigned a[3], n[3];
    ASSERT_EQ(
        std::sscanf(l.c_str(), "f %u//%u %u//%u %u//%u", &a[0], &n[0], &a[1], &n[1], &a[2], &n[2]),
        6)
        << l;
    for (int c = 0; c < 3; ++c) { // each corner's normal is its vertex's (the position here)
      float p[3], q[3];
      std::sscanf(v[a[c] - 1].c_str(), "%f %f %f", &p[0], &p[1], &p[2]);
      std::sscanf(vn[n[c] - 1].c_str(), "%f %f %f", &q[0], &q[1], &q[2]);
      wrong += std::fabs(p[0] - q[0]) + std::fabs(p[1] - q[1]) + std::fabs(p[2] - q[2]) > 1e-5f;
    }
  }
  expect_at_target(faces, s.face_count(), 0.1);
  EXPECT_LE(faces, plain_faces + 2);
  EXPECT_EQ(wrong, 0u) << "output corners whose normal is not their vertex's";
  vrs::tiled::discard(dir);
}

// What a tiled run cannot carry is refused before any tile runs, by name; never dropped.
TEST(Tiled, WhatCannotBeCarriedIsRefusedByName) {
  const std::string dir = temp_dir();
  EXPECT_NE(vrs::tiled::output_refusal("a.ply", "b.obj").find("name the output .ply"),
            std::string::npos);
  EXPECT_NE(vrs::tiled::output_refusal("a.stl", "b.stl").find("reads .ply, .obj or .off"),
            std::string::npos);
  EXPECT_EQ(vrs::tiled::output_refusal("a.PLY", "b.ply"), "");
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                           "property float y\nproperty float z\n";
  std::ofstream(dir + "/wide.ply")
      << head << "element face 1\nproperty list uchar int vertex_indices\n"
      << "property double weight\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 0.5\n";
  EXPECT_NE(run(dir + "/wide.ply", dir + "/o.ply", 0.5, 1 << 30, 1)
                .find("cannot carry the face property 'weight'"),
            std::string::npos);
  std::ofstream(dir + "/edges.ply")
      << head << "element face 1\nproperty list uchar int vertex_indices\n"
      << "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
      << "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n0 1\n";
  EXPECT_NE(run(dir + "/edges.ply", dir + "/o.ply", 0.5, 1 << 30, 1).find("the element 'edge'"),
            std::string::npos);
  std::ofstream(dir + "/colors.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n";
  EXPECT_NE(run(dir + "/colors.off", dir + "/o.off", 0.5, 1 << 30, 1).find("OFF face colors"),
            std::string::npos);
  // Face properties that fit (a color and a signed byte) pass.
  std::ofstream(dir + "/rgb.ply")
      << head << "element face 1\nproperty list uchar int vertex_indices\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty char offset\n"
      << "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 10 20 30 -5\n";
  ASSERT_EQ(run(dir + "/rgb.ply", dir + "/rgb-out.ply", 1.0, 1 << 30, 1), "");
  EXPECT_NE(slurp(dir + "/rgb-out.ply").find("\n3 0 1 2 10 20 30 -5\n"), std::string::npos);
  std::ifstream o(dir + "/o.ply");
  EXPECT_FALSE(o.good()); // no output of a refused run
  vrs::tiled::discard(dir);
}

TEST(Tiled, MemorySizes) {
  EXPECT_EQ(vrs::tiled::parse_memory("2G"), 2ull << 30);
  EXPECT_EQ(vrs::tiled::parse_memory("512M"), 512ull << 20);
  EXPECT_EQ(vrs::tiled::parse_memory("1.5GiB"), 3ull << 29);
  EXPECT_EQ(vrs::tiled::parse_memory("lots"), 0u);
  EXPECT_EQ(vrs::tiled::parse_memory("-1G"), 0u);
  EXPECT_EQ(vrs::tiled::faces_for_memory(2ull << 30), (2ull << 30) / 4 / 200);
}

// Every finding of the streaming readers' fuzzer (fuzz/fuzz_stream.cpp), once fixed: read as
// the fuzzer reads it (first byte modulo 3: PLY, OBJ, OFF), it ends with a message (each was a
// malformed file). Under the sanitizers (scripts/test.sh) an overflow or a bad access aborts.
TEST(StreamReaders, FuzzerFindingsEnd) {
  static const char* const names[3] = {"x.ply", "x.obj", "x.off"};
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(VRS_STREAM_REGRESSIONS)) {
    const std::string data = slurp(entry.path().string());
    ASSERT_FALSE(data.empty()) << entry.path();
    const Read r = read_bytes(data.substr(1), names[(unsigned char)data[0] % 3]);
    EXPECT_NE(r.error, "") << entry.path();
    ++files;
  }
  EXPECT_GE(files, 4); // the directory was found and read
}
