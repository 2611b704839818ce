#include "mesh_checks.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace vrs_test {

namespace {

uint64_t key(uint32_t a, uint32_t b) {
  if (a > b) std::swap(a, b);
  return (uint64_t(a) << 32) | b;
}

std::unordered_map<uint64_t, int> edge_counts(const vrs::Mesh& m) {
  std::unordered_map<uint64_t, int> c;
  for (size_t i = 0; i < m.triangles.size(); i += 3)
    for (int e = 0; e < 3; ++e)
      ++c[key(m.triangles[i + e], m.triangles[i + (e + 1) % 3])];
  return c;
}

struct V3 {
  double x, y, z;
};
V3 pos(const vrs::Mesh& m, uint32_t v) {
  return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
}
V3 sub(V3 a, V3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
V3 cross(V3 a, V3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot(V3 a, V3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

} // namespace

long EdgeStats::euler() const {
  return long(referenced_vertices) - long(edges) + long(faces);
}

EdgeStats edge_stats(const vrs::Mesh& m) {
  EdgeStats s;
  for (auto& [k, n] : edge_counts(m)) {
    ++s.edges;
    s.boundary += n == 1;
    s.nonmanifold += n > 2;
  }
  std::vector<char> used(m.vertex_count(), 0);
  for (uint32_t v : m.triangles)
    used[v] = 1;
  s.referenced_vertices = size_t(std::count(used.begin(), used.end(), 1));
  s.faces = m.face_count();
  return s;
}

std::string check_valid(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r) {
  if (!r.ok) return "refused: " + r.message;
  std::string e = check_indices(out);
  if (e.empty()) e = check_subset(in, out, r);
  if (e.empty() && edge_stats(out).nonmanifold > edge_stats(in).nonmanifold)
    e = "new non-manifold edges";
  if (e.empty() && count_duplicate_directed_edges(out) > count_duplicate_directed_edges(in))
    e = "new repeated directed edges (orientation broken)";
  return e;
}

std::string check_subset(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r) {
  if (r.remap.size() != in.vertex_count()) return "remap has the wrong size";
  uint32_t expect = 0;
  for (size_t v = 0; v < r.remap.size(); ++v) {
    if (r.remap[v] == vrs::kRemoved) continue;
    if (r.remap[v] != expect++) return "remap is not order-preserving at " + std::to_string(v);
    if (std::memcmp(&in.positions[3 * v], &out.positions[3 * r.remap[v]], 3 * sizeof(float)))
      return "vertex " + std::to_string(v) + " moved";
  }
  if (expect != out.vertex_count()) return "output has vertices the remap does not name";
  if (r.face_source.size() != out.face_count()) return "face_source has the wrong size";
  for (size_t f = 0; f < r.face_source.size(); ++f) {
    uint32_t s = r.face_source[f];
    if (s == vrs::kRemoved) continue;
    if (s >= in.face_count()) return "face_source out of range";
    for (int c = 0; c < 3; ++c)
      if (r.remap[in.triangles[3 * s + c]] != out.triangles[3 * f + c])
        return "face " + std::to_string(f) + " is not the input face its source names";
  }
  return {};
}

std::string check_indices(const vrs::Mesh& m) {
  for (size_t i = 0; i < m.triangles.size(); i += 3) {
    uint32_t a = m.triangles[i], b = m.triangles[i + 1], c = m.triangles[i + 2];
    if (a >= m.vertex_count() || b >= m.vertex_count() || c >= m.vertex_count())
      return "index out of range in face " + std::to_string(i / 3);
    if (a == b || b == c || a == c) return "repeated corner in face " + std::to_string(i / 3);
  }
  return {};
}

std::string check_boundary_kept(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r) {
  auto before = edge_counts(in), after = edge_counts(out);
  for (auto& [k, n] : before) {
    if (n != 1) continue;
    uint32_t a = r.remap[k >> 32], b = r.remap[k & 0xffffffffu];
    if (a == vrs::kRemoved || b == vrs::kRemoved) return "a boundary vertex was removed";
    auto it = after.find(key(a, b));
    if (it == after.end() || it->second != 1) return "a boundary edge was lost";
  }
  return {};
}

size_t count_degenerate(const vrs::Mesh& m, double q) {
  size_t n = 0;
  for (size_t i = 0; i < m.triangles.size(); i += 3) {
    V3 a = pos(m, m.triangles[i]), b = pos(m, m.triangles[i + 1]), c = pos(m, m.triangles[i + 2]);
    V3 x = cross(sub(b, a), sub(c, a));
    double sum = dot(sub(b, a), sub(b, a)) + dot(sub(c, b), sub(c, b)) + dot(sub(a, c), sub(a, c));
    double quality = sum > 0 ? 2 * std::sqrt(3.0) * std::sqrt(dot(x, x)) / sum : 0;
    n += quality < q;
  }
  return n;
}

size_t count_flipped(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r) {
  std::vector<V3> normal(in.vertex_count(), V3{0, 0, 0});
  for (size_t i = 0; i < in.triangles.size(); i += 3) {
    V3 x = cross(sub(pos(in, in.triangles[i + 1]), pos(in, in.triangles[i])),
                 sub(pos(in, in.triangles[i + 2]), pos(in, in.triangles[i])));
    for (int c = 0; c < 3; ++c) {
      V3& n = normal[in.triangles[i + c]];
      n = {n.x + x.x, n.y + x.y, n.z + x.z};
    }
  }
  std::vector<uint32_t> old_of(out.vertex_count());
  for (size_t v = 0; v < r.remap.size(); ++v)
    if (r.remap[v] != vrs::kRemoved) old_of[r.remap[v]] = uint32_t(v);
  size_t flipped = 0;
  for (size_t i = 0; i < out.triangles.size(); i += 3) {
    V3 x = cross(sub(pos(out, out.triangles[i + 1]), pos(out, out.triangles[i])),
                 sub(pos(out, out.triangles[i + 2]), pos(out, out.triangles[i])));
    V3 s{0, 0, 0};
    for (int c = 0; c < 3; ++c) {
      V3 n = normal[old_of[out.triangles[i + c]]];
      double l = std::sqrt(dot(n, n));
      if (l > 0) s = {s.x + n.x / l, s.y + n.y / l, s.z + n.z / l};
    }
    flipped += dot(x, s) < 0;
  }
  return flipped;
}

size_t count_duplicate_directed_edges(const vrs::Mesh& m) {
  std::unordered_map<uint64_t, int> c;
  size_t dup = 0;
  for (size_t i = 0; i < m.triangles.size(); i += 3)
    for (int e = 0; e < 3; ++e) {
      uint64_t k = (uint64_t(m.triangles[i + e]) << 32) | m.triangles[i + (e + 1) % 3];
      dup += ++c[k] > 1;
    }
  return dup;
}

} // namespace vrs_test
