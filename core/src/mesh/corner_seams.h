// Seams of per-corner data (texture coordinates, normals, colors): the edges a simplification
// keeps so that no face spans two sides of one.
#pragma once

#include <cstdint>
#include <vector>

#include "vrs/simplify.h"

namespace vrs {

// Edges of `m` across which the corners' keys differ at either end (equal keys: same data),
// as vertex pairs: the seams of that data.
std::vector<uint32_t> key_seams(const Mesh& m, const std::vector<uint32_t>& corner_key);

} // namespace vrs
