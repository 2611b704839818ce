#include "make_inputs.h"

#include <cmath>
#include <fstream>
#include <random>

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

} // namespace vrs_bench
