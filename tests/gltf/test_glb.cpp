// The levels-of-detail .glb (vrs/glb.h), read back byte by byte: the container, the streaming
// layout (the coarsest level's indices and vertex prefix first), every level's triangles on
// the input's positions, and per-corner data split into glTF vertices at seams. Khronos'
// validator and three.js check the same files from tests/web/.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <set>

#include "test_meshes.h"
#include "vrs/glb.h"

using namespace vrs;

namespace {

std::vector<uint8_t> read_all(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), {}};
}

uint32_t u32(const std::vector<uint8_t>& b, size_t at) {
  uint32_t x;
  std::memcpy(&x, b.data() + at, 4);
  return x;
}

std::string temp_path(const char* name) {
  return ::testing::TempDir() + name;
}

// An icosphere's chain at 100/50/10/1 %, with normals (a sphere's normals are its positions).
struct SphereChain {
  Mesh in = vrs_test::icosphere(4);
  LodChain chain;
  std::vector<float> normals;
  GlbAttributes attributes;
  SphereChain() {
    Options o;
    o.threads = 1;
    chain = simplify_lods(in, {1.0, 0.5, 0.1, 0.01}, o);
    normals = in.positions;
    attributes.normals = normals.data();
  }
  SphereChain(const SphereChain&) = delete; // `attributes` points into `normals`
};

} // namespace

TEST(Glb, LevelsReadBackFromTheStreamingLayout) {
  const SphereChain sphere;
  const Mesh& in = sphere.in;
  const LodChain& chain = sphere.chain;
  ASSERT_TRUE(chain.ok);
  GlbAttributes a = sphere.attributes;
  GlbLayout layout;
  const std::string path = temp_path("levels.glb");
  ASSERT_EQ(write_glb(path, in.positions.data(), in.vertex_count(), chain, a, &layout), "");
  const std::vector<uint8_t> b = read_all(path);
  ASSERT_EQ(b.size(), layout.file_bytes);
  EXPECT_EQ(u32(b, 0), 0x46546C67u); // glTF
  EXPECT_EQ(u32(b, 4), 2u);
  EXPECT_EQ(u32(b, 8), b.size());
  const uint32_t json_bytes = u32(b, 12);
  EXPECT_EQ(u32(b, 16), 0x4E4F534Au);
  EXPECT_EQ(json_bytes % 4, 0u);
  const std::string json(b.begin() + 20, b.begin() + 20 + json_bytes);
  EXPECT_NE(json.find("\"MSFT_lod\":{\"ids\":[1,2,3]}"), std::string::npos);
  EXPECT_NE(json.find("MSFT_screencoverage"), std::string::npos);
  EXPECT_EQ(u32(b, 20 + json_bytes + 4), 0x004E4942u);
  const size_t bin = 20 + json_bytes + 8;
  EXPECT_EQ(u32(b, 20 + json_bytes), b.size() - bin);

  // The coarsest level first: its indices, then the vertices, from the chunk's start.
  const auto& coarse = layout.levels.back();
  EXPECT_EQ(coarse.index_offset, bin);
  EXPECT_EQ(layout.vertex_offset, bin + coarse.index_bytes);
  EXPECT_EQ(coarse.bytes_to_draw, bin + coarse.index_bytes + coarse.vertex_bytes);
  EXPECT_LT(double(coarse.bytes_to_draw), 0.05 * double(b.size()));
  EXPECT_EQ(layout.vertex_stride, 24u);              // position and normal
  EXPECT_EQ(layout.vertex_count, in.vertex_count()); // no corner data: no split

  for (size_t k = 0; k < chain.levels.size(); ++k) {
    const LodLevel& l = chain.levels[k];
    const auto& L = layout.levels[k];
    EXPECT_EQ(L.faces * 3, l.triangles.size());
    EXPECT_EQ(L.vertex_count, l.vertex_count);
    if (k + 1 < chain.levels.size()) { // finer levels' indices come after the vertices
      EXPECT_GT(L.index_offset, layout.vertex_offset);
    }
    const bool wide = L.vertex_count >= 65535;
    for (size_t c = 0; c < l.triangles.size(); ++c) {
      uint32_t i = 0;
      std::memcpy(&i, b.data() + L.index_offset + c * (wide ? 4 : 2), wide ? 4 : 2);
      ASSERT_LT(i, L.vertex_count) << "level " << k << " reads past its prefix";
      float p[3], n[3];
      std::memcpy(p, b.data() + layout.vertex_offset + i * 24, 12);
      std::memcpy(n, b.data() + layout.vertex_offset + i * 24 + 12, 12);
      const uint32_t v = chain.vertices[l.triangles[c]];
      ASSERT_EQ(std::memcmp(p, &in.positions[3 * v], 12), 0) << "positions are the input's";
      EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-5);
    }
  }
}

TEST(Glb, CornerDataSplitsVerticesAtSeamsOnly) {
  // Two texture charts on a grid: the seam column's vertices become two glTF vertices each,
  // at every level; nothing else is split.
  const int n = 16;
  const Mesh in = vrs_test::grid(n, 0.0f);
  const float x_seam = in.positions[3 * (n / 2)];
  std::vector<uint32_t> keys(in.triangles.size());
  std::vector<float> uvs(2 * in.triangles.size());
  for (size_t f = 0; f < in.face_count(); ++f) {
    float x = 0;
    for (int c = 0; c < 3; ++c)
      x += in.positions[3 * in.triangles[3 * f + c]] / 3;
    const uint32_t chart = x < x_seam ? 0 : 1;
    for (int c = 0; c < 3; ++c) {
      const uint32_t v = in.triangles[3 * f + c];
      keys[3 * f + c] = chart;
      uvs[2 * (3 * f + c)] = in.positions[3 * v] + float(chart) * 10; // charts apart
      uvs[2 * (3 * f + c) + 1] = in.positions[3 * v + 1];
    }
  }
  Options o;
  o.threads = 1;
  const LodChain chain = simplify_lods(in, {1.0, 0.3}, o, &keys);
  ASSERT_TRUE(chain.ok);
  GlbAttributes a;
  a.corner_uvs = uvs.data();
  a.texture_uri = "chart image.png";
  GlbLayout layout;
  const std::string path = temp_path("seams.glb");
  ASSERT_EQ(write_glb(path, in.positions.data(), in.vertex_count(), chain, a, &layout), "");
  EXPECT_EQ(layout.vertex_stride, 20u);
  EXPECT_EQ(layout.vertex_count, in.vertex_count() + (n + 1)) << "one more per seam vertex";
  const std::vector<uint8_t> b = read_all(path);
  const std::string json(b.begin() + 20, b.begin() + 20 + u32(b, 12));
  EXPECT_NE(json.find("\"uri\":\"chart%20image.png\""), std::string::npos);
  // The coarse level: every face's texture coordinates from one chart (u < 10 or u >= 10).
  const auto& L = layout.levels[1];
  for (size_t t = 0; t < L.faces; ++t) {
    std::set<int> charts;
    for (int c = 0; c < 3; ++c) {
      uint16_t i;
      std::memcpy(&i, b.data() + L.index_offset + 2 * (3 * t + c), 2);
      float uv[2];
      std::memcpy(uv, b.data() + layout.vertex_offset + i * 20 + 12, 8);
      charts.insert(uv[0] >= 9.5f ? 1 : 0);
    }
    EXPECT_EQ(charts.size(), 1u) << "face " << t;
  }
}

TEST(Glb, RefusesWhatGltfCannotHoldAndLeavesNoFile) {
  Mesh in = vrs_test::icosphere(2);
  Options o;
  const LodChain chain = simplify_lods(in, {1.0}, o);
  ASSERT_TRUE(chain.ok);
  in.positions[0] = std::numeric_limits<float>::quiet_NaN();
  const std::string path = temp_path("nan.glb");
  std::remove(path.c_str());
  const std::string err = write_glb(path, in.positions.data(), in.vertex_count(), chain, {});
  EXPECT_NE(err.find("non-finite"), std::string::npos) << err;
  EXPECT_FALSE(std::ifstream(path).good());
  // Corner data without corner sources, and an unwritable path.
  std::vector<float> uvs(2 * in.triangles.size());
  GlbAttributes a;
  a.corner_uvs = uvs.data();
  in.positions[0] = 0;
  EXPECT_NE(write_glb(path, in.positions.data(), in.vertex_count(), chain, a), "");
  EXPECT_NE(write_glb("/nonexistent-dir/x.glb", in.positions.data(), in.vertex_count(), chain, {}),
            "");
}

#ifdef VRS_HAVE_MESHOPTIMIZER
#include <meshoptimizer.h>

#include "meshopt_streams.h"

// Compressed (EXT_meshopt_compression), decoded with meshoptimizer's own decoder: each level's
// triangles are the plain file's, vertex records bit for bit (lossless); each coarser level's
// vertices end on a block of the vertex codec, so its first bytes of the stream and the tail
// decode alone; and the block size the writer assumes is the encoder's (a prefix one vertex
// past a block is not a prefix of the stream's bytes).
TEST(Glb, CompressedLevelsAreThePlainOnesAndEachStreamsAlone) {
  const SphereChain sphere;
  const Mesh& in = sphere.in;
  const LodChain& chain = sphere.chain;
  ASSERT_TRUE(chain.ok);
  GlbAttributes a = sphere.attributes;
  GlbLayout plain, packed;
  ASSERT_EQ(
      write_glb(temp_path("plain.glb"), in.positions.data(), in.vertex_count(), chain, a, &plain),
      "");
  a.compress = true;
  const std::string path = temp_path("packed.glb");
  ASSERT_EQ(write_glb(path, in.positions.data(), in.vertex_count(), chain, a, &packed), "");
  EXPECT_TRUE(packed.compressed);
  EXPECT_LT(packed.file_bytes, plain.file_bytes * 3 / 4);
  const std::vector<uint8_t> b = read_all(path);
  const uint32_t json_bytes = u32(b, 12);
  const std::string json(b.begin() + 20, b.begin() + 20 + json_bytes);
  EXPECT_NE(json.find("\"extensionsRequired\":[\"EXT_meshopt_compression\"]"), std::string::npos);
  EXPECT_NE(json.find("\"fallback\":true"), std::string::npos);
  const size_t bin = 20 + json_bytes + 8, stride = packed.vertex_stride;
  const size_t block = meshopt_block_vertices(stride);

  // The whole vertex stream, as the file holds it (between the coarsest indices and the rest).
  const auto& coarse = packed.levels.back();
  const size_t stream_at = packed.vertex_offset;
  const size_t stream_end = packed.levels[packed.levels.size() - 2].index_offset;
  std::vector<uint8_t> records(packed.vertex_count * stride);
  size_t stream_bytes = stream_end - stream_at;
  while (stream_bytes > 0 && meshopt_decodeVertexBuffer(records.data(), packed.vertex_count, stride,
                                                        b.data() + stream_at, stream_bytes) != 0)
    --stream_bytes; // the chunk pads the stream to 4 bytes
  ASSERT_GT(stream_bytes, 0u);
  EXPECT_EQ(coarse.index_offset, bin);
  const size_t tail = std::max<size_t>(stride, 32);
  for (size_t k = 0; k < packed.levels.size(); ++k) {
    const auto& L = packed.levels[k];
    if (k > 0) {
      EXPECT_EQ(L.vertex_count % block, 0u) << "level " << k;
    }
    // Its prefix with the tail decodes alone, to the stream's first records.
    std::vector<uint8_t> prefix(b.begin() + stream_at, b.begin() + stream_at + L.vertex_bytes);
    prefix.insert(prefix.end(), b.begin() + stream_at + stream_bytes - tail,
                  b.begin() + stream_at + stream_bytes);
    std::vector<uint8_t> alone(L.vertex_count * stride);
    ASSERT_EQ(meshopt_decodeVertexBuffer(alone.data(), L.vertex_count, stride, prefix.data(),
                                         prefix.size()),
              0)
        << "level " << k;
    EXPECT_EQ(std::memcmp(alone.data(), records.data(), alone.size()), 0) << "level " << k;
    // Its triangles: the plain level's, each corner the same position and normal.
    const size_t size = L.vertex_count >= 65535 ? 4 : 2;
    std::vector<uint32_t> idx(L.faces * 3);
    std::vector<uint8_t> raw(idx.size() * size);
    size_t packed_bytes = L.index_bytes;
    while (packed_bytes > 0 &&
           meshopt_decodeIndexBuffer(raw.data(), idx.size(), size, b.data() + L.index_offset,
                                     packed_bytes) != 0)
      --packed_bytes;
    ASSERT_GT(packed_bytes, 0u) << "level " << k;
    for (size_t i = 0; i < idx.size(); ++i) {
      if (size == 2) {
        uint16_t s;
        std::memcpy(&s, raw.data() + 2 * i, 2);
        idx[i] = s;
      } else {
        std::memcpy(&idx[i], raw.data() + 4 * i, 4);
      }
    }
    auto key = [&](const uint8_t* base, uint32_t v) {
      return std::string(reinterpret_cast<const char*>(base) + v * stride, stride);
    };
    std::multiset<std::string> got, want;
    for (size_t t = 0; t < idx.size(); t += 3) {
      std::string c[3] = {key(records.data(), idx[t]), key(records.data(), idx[t + 1]),
                          key(records.data(), idx[t + 2])};
      const int m = c[0] <= c[1] && c[0] <= c[2] ? 0 : c[1] <= c[2] ? 1 : 2; // start: least
      got.insert(c[m] + c[(m + 1) % 3] + c[(m + 2) % 3]);
    }
    const LodLevel& l = chain.levels[k];
    for (size_t t = 0; t < l.triangles.size(); t += 3) {
      std::string c[3];
      for (int j = 0; j < 3; ++j) {
        const uint32_t v = chain.vertices[l.triangles[t + j]];
        float rec[6] = {in.positions[3 * v], in.positions[3 * v + 1], in.positions[3 * v + 2]};
        const double len =
            std::sqrt(double(rec[0]) * rec[0] + double(rec[1]) * rec[1] + double(rec[2]) * rec[2]);
        for (int c3 = 0; c3 < 3; ++c3)
          rec[3 + c3] = float(sphere.normals[3 * v + c3] / len);
        c[j] = std::string(reinterpret_cast<const char*>(rec), 24);
      }
      const int m = c[0] <= c[1] && c[0] <= c[2] ? 0 : c[1] <= c[2] ? 1 : 2;
      want.insert(c[m] + c[(m + 1) % 3] + c[(m + 2) % 3]);
    }
    EXPECT_TRUE(got == want) << "level " << k;
  }
  // The block the writer assumes is the encoder's: a prefix one record past a block is not.
  std::vector<uint8_t> full(meshopt_encodeVertexBufferBound(block + 1, stride));
  full.resize(
      meshopt_encodeVertexBuffer(full.data(), full.size(), records.data(), block + 1, stride));
  std::vector<uint8_t> first(meshopt_encodeVertexBufferBound(block, stride));
  first.resize(
      meshopt_encodeVertexBuffer(first.data(), first.size(), records.data(), block, stride));
  EXPECT_EQ(std::memcmp(first.data(), full.data(), first.size() - tail), 0);
  CompressedVertices cv;
  EXPECT_NE(compress_vertices(records.data(), block + 1, stride, {block - 1}, cv), "");
}
#endif
