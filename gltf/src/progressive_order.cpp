#include "progressive_order.h"

#include <algorithm>

namespace vrs {

std::vector<std::vector<uint32_t>> insertion_batches(const ProgressiveMesh& p,
                                                     const std::vector<uint32_t>& triangles,
                                                     size_t vertex_count, size_t window) {
  constexpr uint32_t kNone = 0xffffffffu;
  const size_t n = p.insertion_count();
  window = std::max<size_t>(window, 1);
  std::vector<uint32_t> last_writer(triangles.size() / 3, kNone), inserter(vertex_count, kNone);
  std::vector<uint32_t> level(n, 0);
  std::vector<std::vector<uint32_t>> batches;
  for (size_t w = 0; w < n; w += window) {
    const size_t end = std::min(n, w + window);
    uint32_t deepest = 0;
    for (size_t r = w; r < end; ++r) {
      uint32_t l = 0;
      auto after = [&](uint32_t q) {
        if (q != kNone && q >= w) l = std::max(l, level[q] + 1);
      };
      for (uint32_t j = p.first[r]; j < p.first[r + 1]; ++j) {
        after(last_writer[p.slots[j]]);
        for (int c = 0; c < 3; ++c) {
          const uint32_t u = triangles[p.corners[3 * size_t(j) + c]];
          if (u != p.vertex[r] && u < vertex_count) after(inserter[u]);
        }
      }
      level[r] = l;
      deepest = std::max(deepest, l);
      for (uint32_t j = p.first[r]; j < p.first[r + 1]; ++j)
        last_writer[p.slots[j]] = uint32_t(r);
      if (p.vertex[r] < vertex_count) inserter[p.vertex[r]] = uint32_t(r);
    }
    const size_t first_batch = batches.size();
    batches.resize(first_batch + deepest + 1);
    for (size_t r = w; r < end; ++r)
      batches[first_batch + level[r]].push_back(uint32_t(r));
  }
  return batches;
}

} // namespace vrs
