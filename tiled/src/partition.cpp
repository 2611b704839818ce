#include "partition.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

namespace vrs::tiled {

namespace {

constexpr int kFine = 64;               // fine cells per axis: the histogram's resolution
constexpr size_t kOpenTiles = 400;      // tile files written per pass (open file limit)
constexpr uint32_t kNone = 0xffffffffu; // vertex of no tile yet
constexpr uint32_t kShared = 0xfffffffeu;
constexpr int kShift = 3; // fine cells the octree moves by on even levels

int fine(const Box& box, const FaceRecord& r, int axis) {
  const float c = (r.p[0][axis] + r.p[1][axis] + r.p[2][axis]) / 3.0f;
  const float extent = box.hi[axis] - box.lo[axis];
  if (!std::isfinite(c) || !(extent > 0)) return 0;
  const int i = int((c - box.lo[axis]) / extent * kFine);
  return std::min(std::max(i, 0), kFine - 1);
}

size_t fine_cell(const Box& box, const FaceRecord& r) {
  return (size_t(fine(box, r, 0)) * kFine + fine(box, r, 1)) * kFine + fine(box, r, 2);
}

// Tiles as the leaves of an octree over the fine cells, split until a leaf holds at most
// `budget` faces: tiles near the budget where the mesh is dense, large ones where it is
// sparse. On shifted levels the octree's origin moves by `shift` fine cells, so that the
// previous level's borders fall inside tiles. Returns fine cell -> tile (kNone: no face).
std::vector<uint32_t> octree_tiles(const std::vector<uint32_t>& hist, uint64_t budget, int shift,
                                   bool halves, uint32_t& tiles) {
  // Prefix sums over the shifted, padded domain [0, 128)^3 for O(1) box counts.
  constexpr int kDom = 2 * kFine, kP = kDom + 1;
  std::vector<uint64_t> pre(size_t(kP) * kP * kP, 0);
  auto at = [&](int x, int y, int z) -> uint64_t& { return pre[(size_t(x) * kP + y) * kP + z]; };
  for (int x = 0; x < kDom; ++x)
    for (int y = 0; y < kDom; ++y)
      for (int z = 0; z < kDom; ++z) {
        const int fx = x - shift, fy = y - shift, fz = z - shift;
        const bool in = fx >= 0 && fy >= 0 && fz >= 0 && fx < kFine && fy < kFine && fz < kFine;
        const uint64_t h = in ? hist[(size_t(fx) * kFine + fy) * kFine + fz] : 0;
        at(x + 1, y + 1, z + 1) = h + at(x, y + 1, z + 1) + at(x + 1, y, z + 1) +
                                  at(x + 1, y + 1, z) - at(x, y, z + 1) - at(x, y + 1, z) -
                                  at(x + 1, y, z) + at(x, y, z);
      }
  auto count = [&](int x, int y, int z, int n) {
    return at(x + n, y + n, z + n) - at(x, y + n, z + n) - at(x + n, y, z + n) -
           at(x + n, y + n, z) + at(x, y, z + n) + at(x, y + n, z) + at(x + n, y, z) - at(x, y, z);
  };
  std::vector<uint32_t> tile_of(hist.size(), kNone);
  tiles = 0;
  std::function<void(int, int, int, int)> visit = [&](int x, int y, int z, int n) {
    const uint64_t c = count(x, y, z, n);
    if (c == 0) return;
    if (c <= budget || n == 1) {
      for (int i = x; i < x + n; ++i)
        for (int j = y; j < y + n; ++j)
          for (int k = z; k < z + n; ++k) {
            const int fx = i - shift, fy = j - shift, fz = k - shift;
            if (fx >= 0 && fy >= 0 && fz >= 0 && fx < kFine && fy < kFine && fz < kFine)
              tile_of[(size_t(fx) * kFine + fy) * kFine + fz] = tiles;
          }
      ++tiles;
      return;
    }
    const int h = n / 2;
    for (int i = 0; i < 8; ++i)
      visit(x + (i & 4 ? h : 0), y + (i & 2 ? h : 0), z + (i & 1 ? h : 0), h);
  };
  // Halves: a box splits in two at the cell plane nearest its median along its longest side,
  // so leaves hold half a budget to a budget (the octree's, an eighth to a budget).
  auto box_count = [&](const int lo[3], const int hi[3]) {
    return at(hi[0], hi[1], hi[2]) - at(lo[0], hi[1], hi[2]) - at(hi[0], lo[1], hi[2]) -
           at(hi[0], hi[1], lo[2]) + at(lo[0], lo[1], hi[2]) + at(lo[0], hi[1], lo[2]) +
           at(hi[0], lo[1], lo[2]) - at(lo[0], lo[1], lo[2]);
  };
  std::function<void(const int*, const int*)> halve = [&](const int* lo, const int* hi) {
    const uint64_t c = box_count(lo, hi);
    if (c == 0) return;
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
    if (c <= budget || hi[axis] - lo[axis] == 1) {
      for (int i = lo[0]; i < hi[0]; ++i)
        for (int j = lo[1]; j < hi[1]; ++j)
          for (int k = lo[2]; k < hi[2]; ++k) {
            const int fx = i - shift, fy = j - shift, fz = k - shift;
            if (fx >= 0 && fy >= 0 && fz >= 0 && fx < kFine && fy < kFine && fz < kFine)
              tile_of[(size_t(fx) * kFine + fy) * kFine + fz] = tiles;
          }
      ++tiles;
      return;
    }
    int cut = lo[axis] + 1;
    for (int m = lo[axis] + 1; m < hi[axis]; ++m) {
      int h2[3] = {hi[0], hi[1], hi[2]};
      h2[axis] = m;
      cut = m;
      if (2 * box_count(lo, h2) >= c) break;
    }
    int mid_hi[3] = {hi[0], hi[1], hi[2]}, mid_lo[3] = {lo[0], lo[1], lo[2]};
    mid_hi[axis] = cut, mid_lo[axis] = cut;
    halve(lo, mid_hi);
    halve(mid_lo, hi);
  };
  if (halves) {
    const int lo[3] = {0, 0, 0}, hi[3] = {kDom, kDom, kDom};
    halve(lo, hi);
  } else {
    visit(0, 0, 0, kDom);
  }
  return tile_of;
}

} // namespace

uint64_t partition(const std::string& dir, int level, uint64_t vertex_count, const Box& box,
                   uint64_t faces_per_tile, bool keys, bool halves, const FaceSource& source) {
  std::vector<uint32_t> hist(size_t(kFine) * kFine * kFine, 0);
  source([&](const FaceRecord& r) { ++hist[fine_cell(box, r)]; });
  uint32_t tiles = 0;
  const std::vector<uint32_t> tile_of =
      octree_tiles(hist, faces_per_tile, level % 2 == 0 ? kShift : 0, halves, tiles);
  hist = {};
  auto tile = [&](const FaceRecord& r) { return tile_of[fine_cell(box, r)]; };

  std::vector<uint32_t> owner(vertex_count, kNone); // which tile each vertex is in
  source([&](const FaceRecord& r) {
    const uint32_t t = tile(r);
    for (uint32_t v : r.v)
      owner[v] = owner[v] == kNone || owner[v] == t ? t : kShared;
  });
  make_dir(dir + "/L" + std::to_string(level));
  for (uint32_t first = 0; first < tiles; first += uint32_t(kOpenTiles)) {
    const uint32_t last = std::min<uint32_t>(tiles, first + uint32_t(kOpenTiles));
    std::vector<std::unique_ptr<RecordWriter>> out;
    for (uint32_t t = first; t < last; ++t)
      out.push_back(std::make_unique<RecordWriter>(tile_path(dir, level, t, ".in")));
    source([&](const FaceRecord& r) {
      const uint32_t t = tile(r);
      if (t < first || t >= last) return;
      FaceRecord w = r;
      w.shared = uint8_t((owner[r.v[0]] == kShared) | (owner[r.v[1]] == kShared) << 1 |
                         (owner[r.v[2]] == kShared) << 2);
      out[t - first]->write(&w, record_size(keys));
    });
    for (auto& w : out)
      w->commit();
  }
  return tiles;
}

} // namespace vrs::tiled
