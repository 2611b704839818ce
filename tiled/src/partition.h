// Cutting a level's faces into tiles: an octree over a 64^3 grid of the input's bounding box,
// split until each leaf holds at most the tile budget, its origin moved by a few cells on even
// levels so that the previous level's borders fall inside tiles. A face belongs to the tile of
// its centroid. A vertex used by two tiles is marked shared in both; the tile locks it and the
// other corners of its faces (see run_tile): removing a vertex never adds an edge at a tile
// border, so tiles cannot disagree there, and a watertight input joins without a crack.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "tile_files.h"

namespace vrs::tiled {

struct Box {
  float lo[3], hi[3];
};

// Hands every face of the level to the callback, in a fixed order (the output does not
// depend on who runs what).
using FaceSource = std::function<void(const std::function<void(const FaceRecord&)>&)>;

// Writes L<level>/<tile>.in for every non-empty tile (records with keys or short ones);
// returns the number of tiles. `halves`: boxes split in two at the median instead of the
// octree's eight (leaves of half a budget to a budget; for the levels after a stall).
uint64_t partition(const std::string& dir, int level, uint64_t vertex_count, const Box& box,
                   uint64_t faces_per_tile, bool keys, bool halves, const FaceSource& source);

} // namespace vrs::tiled
