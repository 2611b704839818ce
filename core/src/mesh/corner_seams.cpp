#include "mesh/corner_seams.h"

#include <unordered_map>

namespace vrs {

namespace {

uint64_t edge_key(uint32_t a, uint32_t b) {
  return a < b ? uint64_t(a) << 32 | b : uint64_t(b) << 32 | a;
}

} // namespace

std::vector<uint32_t> key_seams(const Mesh& m, const std::vector<uint32_t>& corner_key) {
  struct Seen {
    uint32_t key_a, key_b; // the first face's keys at a and b (edge's own order)
    uint32_t a;
    bool done;
  };
  std::unordered_map<uint64_t, Seen> seen;
  seen.reserve(m.triangles.size());
  std::vector<uint32_t> out;
  for (size_t f = 0; f < m.face_count(); ++f)
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = m.triangles[3 * f + c], b = m.triangles[3 * f + (c + 1) % 3];
      const uint32_t ka = corner_key[3 * f + c], kb = corner_key[3 * f + (c + 1) % 3];
      auto [it, first] = seen.emplace(edge_key(a, b), Seen{ka, kb, a, false});
      if (first || it->second.done) continue;
      it->second.done = true;
      const bool same_a = it->second.a == a ? it->second.key_a == ka : it->second.key_b == ka;
      const bool same_b = it->second.a == a ? it->second.key_b == kb : it->second.key_a == kb;
      if (!same_a || !same_b) out.insert(out.end(), {a, b});
    }
  return out;
}

} // namespace vrs
