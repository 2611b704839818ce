#include "spatial_order.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace vrs {

namespace {

// Spreads the low 21 bits of x to every third bit.
uint64_t spread3(uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffull;
  x = (x | x << 16) & 0x1f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

// Blocks of the loops over vertices and faces, on the workers when given.
constexpr size_t kBlock = 65536;

} // namespace

SpatialOrder spatial_order(std::vector<float>& positions, std::vector<uint32_t>& triangles,
                           Workers* workers) {
  const size_t n = positions.size() / 3, faces = triangles.size() / 3;
  float lo[3], hi[3];
  for (int a = 0; a < 3; ++a)
    lo[a] = std::numeric_limits<float>::max(), hi[a] = -std::numeric_limits<float>::max();
  for (size_t v = 0; v < n; ++v) {
    const float* p = &positions[3 * v];
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) continue;
    for (int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  }
  double scale[3];
  for (int a = 0; a < 3; ++a)
    scale[a] = hi[a] > lo[a] ? double(0x1fffff) / (double(hi[a]) - double(lo[a])) : 0.0;

  // (code, input index) pairs: sorting them orders ties by index, so the result is unique.
  std::vector<std::pair<uint64_t, uint32_t>> keys(n);
  for_each_block(workers, n, kBlock, [&](size_t begin, size_t end) {
    for (size_t v = begin; v < end; ++v) {
      const float* p = &positions[3 * v];
      uint64_t code = std::numeric_limits<uint64_t>::max();
      if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) {
        code = 0;
        for (int a = 0; a < 3; ++a)
          code |= spread3(uint64_t((double(p[a]) - lo[a]) * scale[a])) << a;
      }
      keys[v] = {code, uint32_t(v)};
    }
    // Each block sorted on its own, then merged in pairs (the keys are unique: one order).
    std::sort(keys.begin() + begin, keys.begin() + end);
  });
  for (size_t width = kBlock; width < n; width *= 2) {
    const size_t pairs = (n + 2 * width - 1) / (2 * width);
    auto merge = [&](size_t i) {
      const size_t begin = 2 * width * i, mid = std::min(n, begin + width),
                   end = std::min(n, begin + 2 * width);
      std::inplace_merge(keys.begin() + begin, keys.begin() + mid, keys.begin() + end);
    };
    for_each_on(workers, pairs, merge);
  }

  SpatialOrder order;
  order.vertex_old.resize(n);
  order.vertex_new.resize(n);
  for_each_block(workers, n, kBlock, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      order.vertex_old[i] = keys[i].second;
      order.vertex_new[keys[i].second] = uint32_t(i);
    }
  });
  std::vector<std::pair<uint64_t, uint32_t>>().swap(keys);
  {
    std::vector<float> moved(positions.size());
    for_each_block(workers, n, kBlock, [&](size_t begin, size_t end) {
      for (size_t i = begin; i < end; ++i)
        std::copy_n(&positions[3 * size_t(order.vertex_old[i])], 3, &moved[3 * i]);
    });
    std::copy(moved.begin(), moved.end(), positions.begin()); // same buffer: callers hold it
  }

  // Faces: counting sort by their lowest new corner (stable, linear).
  for_each_block(workers, triangles.size(), kBlock, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i)
      triangles[i] = order.vertex_new[triangles[i]];
  });
  std::vector<uint32_t> start(n + 1, 0);
  for (size_t f = 0; f < faces; ++f)
    ++start[1 + std::min({triangles[3 * f], triangles[3 * f + 1], triangles[3 * f + 2]})];
  for (size_t v = 0; v < n; ++v)
    start[v + 1] += start[v];
  order.face_old.resize(faces);
  for (size_t f = 0; f < faces; ++f)
    order.face_old[start[std::min(
        {triangles[3 * f], triangles[3 * f + 1], triangles[3 * f + 2]})]++] = uint32_t(f);
  std::vector<uint32_t>().swap(start);
  std::vector<uint32_t> moved(triangles.size());
  for_each_block(workers, faces, kBlock, [&](size_t begin, size_t end) {
    for (size_t f = begin; f < end; ++f)
      std::copy_n(&triangles[3 * size_t(order.face_old[f])], 3, &moved[3 * f]);
  });
  std::copy(moved.begin(), moved.end(), triangles.begin());
  return order;
}

} // namespace vrs
