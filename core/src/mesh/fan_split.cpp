#include "mesh/fan_split.h"

namespace vrs {

FanSplit split_fans(std::vector<uint32_t>& tris, size_t n, const Topology& topo,
                    const std::vector<uint32_t>& candidates) {
  FanSplit split;
  std::vector<uint32_t> groups; // per split vertex: its first copy, then how many
  std::vector<uint32_t> from, to, next, faces;
  std::vector<int> fan;
  for (uint32_t v : candidates) {
    const uint32_t m = topo.valence(v);
    if (m < 2 || m > 4 * uint32_t(kMaxRing)) continue; // a hub stays whole (pairs: quadratic)
    faces.assign(topo.faces_of(v), topo.faces_of(v) + m);
    from.resize(m), to.resize(m);
    for (uint32_t i = 0; i < m; ++i) { // face (v, a, b): the directed ring edge a -> b
      const uint32_t* t = &tris[3 * size_t(faces[i])];
      const int c = t[0] == v ? 0 : t[1] == v ? 1 : 2;
      from[i] = t[(c + 1) % 3], to[i] = t[(c + 2) % 3];
    }
    next.assign(m, kNone);
    std::vector<bool> has_pred(m, false);
    bool manifold = true;
    for (uint32_t i = 0; i < m && manifold; ++i)
      for (uint32_t j = i + 1; j < m; ++j) {
        if (from[i] == from[j] || to[i] == to[j]) {
          manifold = false;
          break;
        }
        if (to[i] == from[j]) next[i] = j, has_pred[j] = true;
        if (to[j] == from[i]) next[j] = i, has_pred[i] = true;
      }
    if (!manifold) continue;
    // Chains first (from their first faces, in list order), then cycles.
    fan.assign(m, -1);
    int fans = 0;
    auto walk = [&](uint32_t start) {
      for (uint32_t cur = start; cur != kNone && fan[cur] < 0; cur = next[cur])
        fan[cur] = fans;
      ++fans;
    };
    for (uint32_t i = 0; i < m; ++i)
      if (!has_pred[i]) walk(i);
    for (uint32_t i = 0; i < m; ++i)
      if (fan[i] < 0) walk(i);
    if (fans < 2) continue;
    const uint32_t first = uint32_t(n + split.original.size());
    for (int k = 1; k < fans; ++k)
      split.original.push_back(v);
    for (uint32_t i = 0; i < m; ++i) {
      if (fan[i] == 0) continue;
      uint32_t* t = &tris[3 * size_t(faces[i])];
      for (int c = 0; c < 3; ++c)
        if (t[c] == v) t[c] = first + uint32_t(fan[i] - 1);
    }
    groups.push_back(v), groups.push_back(first), groups.push_back(uint32_t(fans - 1));
  }
  if (split.empty()) return split;
  split.sibling.assign(n + split.original.size(), kNone);
  for (size_t g = 0; g < groups.size(); g += 3) {
    uint32_t prev = groups[g];
    for (uint32_t k = 0; k < groups[g + 2]; ++k)
      split.sibling[prev] = groups[g + 1] + k, prev = groups[g + 1] + k;
    split.sibling[prev] = groups[g];
  }
  return split;
}

} // namespace vrs
