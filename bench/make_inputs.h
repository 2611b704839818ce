// Large inputs for the scaling runs, made here rather than shipped: Loop subdivision of a real
// mesh (vcglib's refinement, as MeshLab's filter) and diamond-square fractal terrains.
#pragma once

#include <cstdint>
#include <string>

#include "vrs/simplify.h"

namespace vrs_bench {

vrs::Mesh loop_subdivide(const vrs::Mesh& in, int levels);
// (2^k + 1)^2 height field, deterministic for a seed; z in the units of the xy spacing.
vrs::Mesh fractal_terrain(int k, uint32_t seed);
// An n x n height field written straight to a binary PLY, a row at a time (never held whole: the
// inputs bigger than memory). Heights: value noise summed over octaves, deterministic. "" or an
// error.
std::string write_streamed_terrain(uint32_t n, const std::string& path);
// Binary little-endian PLY (positions and triangles only). "" or an error.
std::string write_ply(const vrs::Mesh& m, const std::string& path);

} // namespace vrs_bench
