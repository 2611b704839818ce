#include "make_inputs.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <random>
#include <vector>

#include <vcg/complex/complex.h> // before the algorithms, which rely on it

#include <vcg/complex/algorithms/refine_loop.h>
#include <vcg/complex/algorithms/update/topology.h>

namespace vrs_bench {

namespace {

class LVertex;
class LFace;
struct LTypes
    : public vcg::UsedTypes<vcg::Use<LVertex>::AsVertexType, vcg::Use<LFace>::AsFaceType> {};
class LVertex : public vcg::Vertex<LTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f,
                                   vcg::vertex::BitFlags, vcg::vertex::Mark> {};
class LFace : public vcg::Face<LTypes, vcg::face::VertexRef, vcg::face::FFAdj, vcg::face::Normal3f,
                               vcg::face::BitFlags> {};
class LoopMesh : public vcg::tri::TriMesh<std::vector<LVertex>, std::vector<LFace>> {};

} // namespace

vrs::Mesh loop_subdivide(const vrs::Mesh& in, int levels) {
  LoopMesh m;
  auto vi = vcg::tri::Allocator<LoopMesh>::AddVertices(m, in.vertex_count());
  for (size_t v = 0; v < in.vertex_count(); ++v, ++vi)
    vi->P() = vcg::Point3f(in.positions[3 * v], in.positions[3 * v + 1], in.positions[3 * v + 2]);
  auto fi = vcg::tri::Allocator<LoopMesh>::AddFaces(m, in.face_count());
  for (size_t f = 0; f < in.face_count(); ++f, ++fi)
    for (int k = 0; k < 3; ++k)
      fi->V(k) = &m.vert[in.triangles[3 * f + k]];
  for (int l = 0; l < levels; ++l) {
    vcg::tri::UpdateTopology<LoopMesh>::FaceFace(m);
    vcg::tri::RefineOddEven<LoopMesh>(m, vcg::tri::OddPointLoop<LoopMesh>(m),
                                      vcg::tri::EvenPointLoop<LoopMesh>(), 0.0f);
  }
  vrs::Mesh out;
  out.positions.reserve(3 * m.vert.size());
  for (const LVertex& v : m.vert)
    for (int k = 0; k < 3; ++k)
      out.positions.push_back(v.cP()[k]);
  out.triangles.reserve(3 * m.face.size());
  for (const LFace& f : m.face)
    for (int k = 0; k < 3; ++k)
      out.triangles.push_back(uint32_t(vcg::tri::Index(m, f.cV(k))));
  return out;
}

vrs::Mesh fractal_terrain(int k, uint32_t seed) {
  const int n = (1 << k) + 1;
  std::vector<float> h(size_t(n) * n, 0.0f);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  auto at = [&](int x, int y) -> float& { return h[size_t(y) * n + x]; };
  float amp = float(n) * 0.25f;
  for (int step = n - 1; step > 1; step /= 2, amp *= 0.55f) { // roughness 0.55: hilly, not spiky
    const int half = step / 2;
    for (int y = half; y < n; y += step) // diamond
      for (int x = half; x < n; x += step)
        at(x, y) = (at(x - half, y - half) + at(x + half, y - half) + at(x - half, y + half) +
                    at(x + half, y + half)) /
                       4 +
                   amp * u(rng);
    for (int y = 0; y < n; y += half) // square
      for (int x = (y / half) % 2 ? 0 : half; x < n; x += step) {
        float s = 0;
        int c = 0;
        if (x >= half) s += at(x - half, y), ++c;
        if (x + half < n) s += at(x + half, y), ++c;
        if (y >= half) s += at(x, y - half), ++c;
        if (y + half < n) s += at(x, y + half), ++c;
        at(x, y) = s / float(c) + amp * u(rng);
      }
  }
  vrs::Mesh m;
  m.positions.reserve(3 * h.size());
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      m.positions.insert(m.positions.end(), {float(x), float(y), at(x, y)});
  m.triangles.reserve(6 * size_t(n - 1) * (n - 1));
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      uint32_t a = uint32_t(y * n + x), b = a + 1, c = a + uint32_t(n), d = c + 1;
      m.triangles.insert(m.triangles.end(), {a, b, d, a, d, c});
    }
  return m;
}

std::string write_ply(const vrs::Mesh& m, const std::string& path) {
  std::ofstream f(path, std::ios::binary);
  if (!f) return "cannot write " + path;
  f << "ply\nformat binary_little_endian 1.0\nelement vertex " << m.vertex_count()
    << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << m.face_count()
    << "\nproperty list uchar int vertex_indices\nend_header\n";
  f.write(reinterpret_cast<const char*>(m.positions.data()),
          std::streamsize(m.positions.size() * sizeof(float)));
  const unsigned char three = 3;
  for (size_t t = 0; t < m.face_count(); ++t) {
    f.write(reinterpret_cast<const char*>(&three), 1);
    f.write(reinterpret_cast<const char*>(&m.triangles[3 * t]), 12);
  }
  return f ? std::string() : "write failed: " + path;
}

namespace {

// A lattice value in [-1, 1] from a hash of its coordinates: noise without a stored table.
float lattice(uint32_t x, uint32_t y, uint32_t octave) {
  uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ octave * 0xcb1ab31fu;
  h ^= h >> 15, h *= 0x2c1b3c6du, h ^= h >> 12, h *= 0x297a2d39u, h ^= h >> 15;
  return float(h) / 2147483648.0f - 1.0f;
}

float value_noise(float x, float y, uint32_t octave) {
  const float fx = std::floor(x), fy = std::floor(y);
  const uint32_t ix = uint32_t(int64_t(fx)), iy = uint32_t(int64_t(fy));
  float u = x - fx, v = y - fy;
  u = u * u * (3 - 2 * u), v = v * v * (3 - 2 * v); // smoothstep: no creases at lattice lines
  const float a = lattice(ix, iy, octave), b = lattice(ix + 1, iy, octave),
              c = lattice(ix, iy + 1, octave), d = lattice(ix + 1, iy + 1, octave);
  return (a + (b - a) * u) * (1 - v) + (c + (d - c) * u) * v;
}

} // namespace

std::string write_streamed_terrain(uint32_t n, const std::string& path) {
  if (n < 2 || uint64_t(n) * n > 0xffffffffull) return "terrain size out of range";
  std::ofstream f(path, std::ios::binary);
  if (!f) return "cannot write " + path;
  const uint64_t faces = 2ull * (n - 1) * (n - 1);
  f << "ply\nformat binary_little_endian 1.0\nelement vertex " << uint64_t(n) * n
    << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << faces
    << "\nproperty list uchar int vertex_indices\nend_header\n";
  std::vector<float> row(3 * size_t(n));
  for (uint32_t y = 0; y < n; ++y) {
    for (uint32_t x = 0; x < n; ++x) {
      float z = 0, amp = float(n) * 0.05f, freq = 4.0f / float(n); // a few hills across
      for (uint32_t o = 0; freq < 1.0f; ++o, amp *= 0.5f, freq *= 2.0f)
        z += amp * value_noise(float(x) * freq, float(y) * freq, o);
      row[3 * x] = float(x), row[3 * x + 1] = float(y), row[3 * x + 2] = z;
    }
    f.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * sizeof(float)));
  }
  std::vector<unsigned char> rec(2 * 13 * size_t(n - 1));
  for (uint32_t y = 0; y + 1 < n; ++y) {
    unsigned char* p = rec.data();
    for (uint32_t x = 0; x + 1 < n; ++x) {
      const uint32_t a = y * n + x, b = a + 1, c = a + n, d = c + 1;
      const uint32_t tris[6] = {a, b, d, a, d, c};
      for (int t = 0; t < 2; ++t) {
        *p++ = 3;
        std::memcpy(p, tris + 3 * t, 12), p += 12;
      }
    }
    f.write(reinterpret_cast<const char*>(rec.data()), std::streamsize(rec.size()));
  }
  return f ? std::string() : "write failed: " + path;
}

} // namespace vrs_bench
