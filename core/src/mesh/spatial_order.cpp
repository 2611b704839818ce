#include "mesh/spatial_order.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>

#include "base/uninitialized.h"
#include "base/workers.h"

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

// A vertex's Morton code and input index: sorting them orders ties by index (unique).
struct Key {
  uint64_t code;
  uint32_t index;
  bool operator<(const Key& o) const {
    return code < o.code || (code == o.code && index < o.index);
  }
};

} // namespace

SpatialOrder spatial_order(std::vector<float>& positions, std::vector<uint32_t>& triangles,
                           Workers* workers) {
  const size_t n = positions.size() / 3, faces = triangles.size() / 3;
  // The bounding box of the finite positions, block by block (min and max: one result).
  const size_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<std::array<float, 6>> box(blocks);
  for_each_block(workers, n, kBlock, [&](size_t begin, size_t end) {
    auto& b = box[begin / kBlock];
    for (int a = 0; a < 3; ++a)
      b[a] = std::numeric_limits<float>::max(), b[3 + a] = -std::numeric_limits<float>::max();
    for (size_t v = begin; v < end; ++v) {
      const float* p = &positions[3 * v];
      if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) continue;
      for (int a = 0; a < 3; ++a)
        b[a] = std::min(b[a], p[a]), b[3 + a] = std::max(b[3 + a], p[a]);
    }
  });
  float lo[3], hi[3];
  for (int a = 0; a < 3; ++a)
    lo[a] = std::numeric_limits<float>::max(), hi[a] = -std::numeric_limits<float>::max();
  for (const auto& b : box)
    for (int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], b[a]), hi[a] = std::max(hi[a], b[3 + a]);
  double scale[3];
  for (int a = 0; a < 3; ++a)
    scale[a] = hi[a] > lo[a] ? double(0x1fffff) / (double(hi[a]) - double(lo[a])) : 0.0;

  UninitVector<Key> keys(n);
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
  // New -> input index for the move only: the run never needs it (4 bytes a vertex less at
  // its peak; output.cpp walks the input's order through vertex_new).
  UninitVector<uint32_t> vertex_old(n);
  order.vertex_new.resize(n);
  for_each_block(workers, n, kBlock, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      vertex_old[i] = keys[i].index;
      order.vertex_new[keys[i].index] = uint32_t(i);
    }
  });
  UninitVector<Key>().swap(keys);
  {
    UninitVector<float> moved(positions.size());
    for_each_block(workers, n, kBlock, [&](size_t begin, size_t end) {
      for (size_t i = begin; i < end; ++i)
        std::copy_n(&positions[3 * size_t(vertex_old[i])], 3, &moved[3 * i]);
    });
    // Back into the same buffer (callers hold it).
    for_each_block(workers, moved.size(), 3 * kBlock, [&](size_t begin, size_t end) {
      std::copy(moved.begin() + begin, moved.begin() + end, positions.begin() + begin);
    });
  }
  UninitVector<uint32_t>().swap(vertex_old);

  // Faces: counting sort by their lowest new corner (stable, linear).
  for_each_block(workers, triangles.size(), kBlock, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i)
      triangles[i] = order.vertex_new[triangles[i]];
  });
  // A range of lowest corners a thread, each reading every face: counted, then placed in face
  // order (the order of one pass, whatever the threads).
  const size_t ranges = range_count(workers);
  auto lowest = [&](size_t f) {
    return std::min({triangles[3 * f], triangles[3 * f + 1], triangles[3 * f + 2]});
  };
  UninitVector<uint32_t> start(n);
  std::vector<size_t> in_range(ranges + 1, 0);
  for_each_range_on(workers, ranges, [&](size_t r) {
    const auto [lo, hi] = range_of(r, ranges, n);
    std::fill(start.begin() + lo, start.begin() + hi, 0u);
    for (size_t f = 0; f < faces; ++f) {
      const uint32_t v = lowest(f);
      if (v - lo < hi - lo) ++start[v];
    }
    for (size_t v = lo; v < hi; ++v)
      in_range[r + 1] += start[v];
  });
  for (size_t r = 0; r < ranges; ++r)
    in_range[r + 1] += in_range[r];
  order.face_old.resize(faces);
  for_each_range_on(workers, ranges, [&](size_t r) {
    const auto [lo, hi] = range_of(r, ranges, n);
    uint32_t at = uint32_t(in_range[r]);
    for (size_t v = lo; v < hi; ++v) {
      const uint32_t count = start[v];
      start[v] = at;
      at += count;
    }
    for (size_t f = 0; f < faces; ++f) {
      const uint32_t v = lowest(f);
      if (v - lo < hi - lo) order.face_old[start[v]++] = uint32_t(f);
    }
  });
  UninitVector<uint32_t>().swap(start);
  UninitVector<uint32_t> moved(triangles.size());
  for_each_block(workers, faces, kBlock, [&](size_t begin, size_t end) {
    for (size_t f = begin; f < end; ++f)
      std::copy_n(&triangles[3 * size_t(order.face_old[f])], 3, &moved[3 * f]);
  });
  for_each_block(workers, moved.size(), 3 * kBlock, [&](size_t begin, size_t end) {
    std::copy(moved.begin() + begin, moved.begin() + end, triangles.begin() + begin);
  });
  return order;
}

} // namespace vrs
