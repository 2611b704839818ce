// Tiled runs: the streaming readers on every layout they take and refuse, and whole runs on a
// closed mesh cut into many tiles: watertight, input vertices only, the target, the same output
// on one worker or three, and bad input or a bad work directory as clear errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "mesh_stream.h"
#include "test_meshes.h"
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
  sink.vertex = [&](const float p[3]) { r.v.insert(r.v.end(), p, p + 3); };
  sink.triangle = [&](const int64_t t[3]) { r.t.insert(r.t.end(), t, t + 3); };
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
                int workers) {
  const std::string dir = out + ".tiles";
  try {
    vrs::tiled::Settings s;
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

TEST(Tiled, BadInputAndWorkDirectoriesAreClearErrorsAndLeaveNothing) {
  const std::string dir = temp_dir();
  std::ofstream(dir + "/range.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n";
  EXPECT_NE(run(dir + "/range.obj", dir + "/o.ply", 0.5, 1 << 30, 1).find("out of range"),
            std::string::npos);
  std::ofstream(dir + "/nan.obj")
      << "v 0 0 0\nv 1 0 0\nv nan 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n";
  EXPECT_EQ(run(dir + "/nan.obj", dir + "/nan.ply", 0.5, 1 << 30, 1), ""); // kept, valid
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

TEST(Tiled, MemorySizes) {
  EXPECT_EQ(vrs::tiled::parse_memory("2G"), 2ull << 30);
  EXPECT_EQ(vrs::tiled::parse_memory("512M"), 512ull << 20);
  EXPECT_EQ(vrs::tiled::parse_memory("1.5GiB"), 3ull << 29);
  EXPECT_EQ(vrs::tiled::parse_memory("lots"), 0u);
  EXPECT_EQ(vrs::tiled::parse_memory("-1G"), 0u);
  EXPECT_EQ(vrs::tiled::faces_for_memory(2ull << 30), (2ull << 30) / 4 / 200);
}

// Every finding of the streaming readers' fuzzer (fuzz/fuzz_stream.cpp), once fixed: read as
// the fuzzer reads it (first byte: even PLY, odd OBJ), it ends, with or without a message.
TEST(StreamReaders, FuzzerFindingsEnd) {
  int files = 0;
  for (const char* name : {"ply-element-without-properties-and-a-negative-count"}) {
    const std::string data = slurp(std::string(VRS_STREAM_REGRESSIONS) + "/" + name);
    ASSERT_FALSE(data.empty()) << name;
    const Read r = read_bytes(data.substr(1), data[0] & 1 ? "x.obj" : "x.ply");
    EXPECT_NE(r.error, "") << name;
    ++files;
  }
  EXPECT_EQ(files, 1);
}
