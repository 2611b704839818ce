// The order a progressive file writes its records in: the run's, except within each window of
// records, where those that do not wait for one another form a batch (docs/progressive.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "vrs/progressive.h"

namespace vrs {

// Batches of insertions, in the order a decoder applies them. Within each window of `window`
// insertions, batch b holds those that wait for b others of the window in a chain (for the
// faces they replace or the vertices they join); insertions of one batch touch disjoint faces,
// so any order among them rebuilds the same mesh. `triangles` names the input vertex of each
// input corner; `vertex_count` bounds those vertices.
std::vector<std::vector<uint32_t>> insertion_batches(const ProgressiveMesh& p,
                                                     const std::vector<uint32_t>& triangles,
                                                     size_t vertex_count, size_t window);

} // namespace vrs
