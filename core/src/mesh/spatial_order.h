// Vertices and faces renumbered along a Z-order (Morton) curve of the positions: a vertex's
// neighbours and faces then sit near it in memory, so the time per face stays flat as meshes
// outgrow the caches. The driver renumbers on the way in and restores the order on the way out.
#pragma once

#include <cstdint>
#include <vector>

#include "base/uninitialized.h"
#include "base/workers.h"

namespace vrs {

struct SpatialOrder {                // written whole by the workers (not zero-filled first)
  UninitVector<uint32_t> vertex_new; // input vertex index -> new index
  UninitVector<uint32_t> face_old;   // new face slot -> input slot (| kRewrittenSlot)
};

// In face_old: the slot's face was rewritten by the run (a face the re-triangulation made).
// Kept there, not in an array of its own (4 bytes an input face less at the run's peak); the
// input's faces are fewer than 2^31 (input_check.cpp).
constexpr uint32_t kRewrittenSlot = 0x80000000u;

// Renumbers `positions` (3 a vertex) and `triangles` in place (same buffers): vertices by the
// Morton code of their position in the bounding box of the finite ones (non-finite ones last, ties
// by index), faces by their lowest new corner (stable). Returns the permutations. The codes,
// the sort and the moves run on `workers` when given (the same result: the keys are unique).
SpatialOrder spatial_order(std::vector<float>& positions, std::vector<uint32_t>& triangles,
                           Workers* workers = nullptr);

} // namespace vrs
