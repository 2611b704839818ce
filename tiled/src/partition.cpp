#include "partition.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace vrs::tiled {

namespace {

constexpr int kFine = 64;               // fine cells per axis: the histogram's resolution
constexpr size_t kOpenTiles = 400;      // tile files written per pass (open file limit)
constexpr uint32_t kNone = 0xffffffffu; // vertex of no tile yet
constexpr uint32_t kShared = 0xfffffffeu;

struct Grid {
  const Box& box;
  int k = kFine, shift = 0, dims = 1; // coarse cell = k fine cells; shifted by `shift` fine cells

  int fine(const FaceRecord& r, int axis) const {
    const float c = (r.p[0][axis] + r.p[1][axis] + r.p[2][axis]) / 3.0f;
    const float extent = box.hi[axis] - box.lo[axis];
    if (!std::isfinite(c) || !(extent > 0)) return 0;
    const int i = int((c - box.lo[axis]) / extent * kFine);
    return std::min(std::max(i, 0), kFine - 1);
  }
  uint64_t cell(const FaceRecord& r) const {
    uint64_t id = 0;
    for (int a = 0; a < 3; ++a)
      id = id * uint64_t(dims) + uint64_t((fine(r, a) + shift) / k);
    return id;
  }
};

// The largest power-of-two cell whose fullest cell holds at most `budget` faces.
void choose_cell(Grid& g, const std::vector<uint32_t>& hist, uint64_t total, uint64_t budget,
                 bool shifted) {
  if (total <= budget) { // one tile: the whole mesh, nothing locked
    g.k = 2 * kFine, g.shift = 0, g.dims = 1;
    return;
  }
  for (int k = kFine; k >= 1; k /= 2) {
    const int shift = shifted ? k / 2 : 0, dims = (kFine - 1 + shift) / k + 1;
    std::vector<uint64_t> counts(size_t(dims) * dims * dims, 0);
    for (int x = 0; x < kFine; ++x)
      for (int y = 0; y < kFine; ++y)
        for (int z = 0; z < kFine; ++z)
          counts[(size_t((x + shift) / k) * dims + (y + shift) / k) * dims + (z + shift) / k] +=
              hist[(size_t(x) * kFine + y) * kFine + z];
    g.k = k, g.shift = shift, g.dims = dims;
    if (*std::max_element(counts.begin(), counts.end()) <= budget) return;
  }
}

} // namespace

uint64_t partition(const std::string& dir, int level, uint64_t vertex_count, const Box& box,
                   uint64_t faces_per_tile, const FaceSource& source) {
  Grid g{box};
  std::vector<uint32_t> hist(size_t(kFine) * kFine * kFine, 0);
  uint64_t total = 0;
  source([&](const FaceRecord& r) {
    ++hist[(size_t(g.fine(r, 0)) * kFine + g.fine(r, 1)) * kFine + g.fine(r, 2)];
    ++total;
  });
  choose_cell(g, hist, total, faces_per_tile, level % 2 == 0);
  hist = {};

  // Dense tile ids over the non-empty cells, in cell order; which tile each vertex is in.
  std::vector<uint32_t> tile_of_cell(size_t(g.dims) * g.dims * g.dims, kNone);
  std::vector<uint32_t> owner(vertex_count, kNone);
  source([&](const FaceRecord& r) { tile_of_cell[g.cell(r)] = 0; });
  uint32_t tiles = 0;
  for (uint32_t& t : tile_of_cell)
    if (t != kNone) t = tiles++;
  source([&](const FaceRecord& r) {
    const uint32_t t = tile_of_cell[g.cell(r)];
    for (uint32_t v : r.v)
      owner[v] = owner[v] == kNone || owner[v] == t ? t : kShared;
  });
  // Locked: a shared vertex, and every corner of a face that has one.
  std::vector<uint8_t> lock(vertex_count, 0);
  source([&](const FaceRecord& r) {
    if (owner[r.v[0]] == kShared || owner[r.v[1]] == kShared || owner[r.v[2]] == kShared)
      lock[r.v[0]] = lock[r.v[1]] = lock[r.v[2]] = 1;
  });
  owner = {};

  make_dir(dir + "/L" + std::to_string(level));
  for (uint32_t first = 0; first < tiles; first += uint32_t(kOpenTiles)) {
    const uint32_t last = std::min<uint32_t>(tiles, first + uint32_t(kOpenTiles));
    std::vector<std::unique_ptr<RecordWriter>> out;
    for (uint32_t t = first; t < last; ++t)
      out.push_back(std::make_unique<RecordWriter>(tile_path(dir, level, t, ".in")));
    source([&](const FaceRecord& r) {
      const uint32_t t = tile_of_cell[g.cell(r)];
      if (t < first || t >= last) return;
      FaceRecord w = r;
      w.locked = uint8_t(lock[r.v[0]] | lock[r.v[1]] << 1 | lock[r.v[2]] << 2);
      out[t - first]->write(&w, sizeof w);
    });
    for (auto& w : out)
      w->commit();
  }
  return tiles;
}

} // namespace vrs::tiled
