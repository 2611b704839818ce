// Vertices and faces renumbered along a Z-order (Morton) curve of the positions: a vertex's
// neighbours and faces then sit near it in memory, so the time per face stays flat as meshes
// outgrow the caches. The driver renumbers on the way in and restores the order on the way out.
#pragma once

#include <cstdint>
#include <vector>

#include "uninitialized.h"
#include "workers.h"

namespace vrs {

struct SpatialOrder {                // written whole by the workers (not zero-filled first)
  UninitVector<uint32_t> vertex_old; // new vertex index -> input index
  UninitVector<uint32_t> vertex_new; // input vertex index -> new index
  UninitVector<uint32_t> face_old;   // new face slot -> input slot
};

// Renumbers `positions` (3 a vertex) and `triangles` in place (same buffers): vertices by the
// Morton code of their position in the bounding box of the finite ones (non-finite ones last, ties
// by index), faces by their lowest new corner (stable). Returns the permutations. The codes,
// the sort and the moves run on `workers` when given (the same result: the keys are unique).
SpatialOrder spatial_order(std::vector<float>& positions, std::vector<uint32_t>& triangles,
                           Workers* workers = nullptr);

} // namespace vrs
