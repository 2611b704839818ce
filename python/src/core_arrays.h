// The numpy side of the core's bindings, shared by core_module.cpp (simplify),
// lods_module.cpp (levels of detail) and progressive_module.cpp: arrays read through their strides,
// results handed to numpy without a copy, the report as the CLI's JSON keys, the options from
// keywords.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/string.h>

#include "vrs/simplify.h"

namespace vrs_py {

namespace nb = nanobind;
using AnyArray = nb::ndarray<nb::ro, nb::device::cpu>;

std::vector<float> read_positions(const AnyArray& a);

// A run's input as lods() and progressive() take it: the mesh, seam pairs and corner keys
// (empty when not given), read and checked.
struct RunInput {
  vrs::Mesh mesh;
  std::vector<uint32_t> seams, keys;
  bool has_keys = false;
};
RunInput read_run_input(const AnyArray& vertices, const AnyArray& faces, const AnyArray* seams,
                        const AnyArray* corner_keys);
// (rows, columns) integer indices, each < bound (else a ValueError naming `what` and the row).
std::vector<uint32_t> read_indices(const AnyArray& a, size_t bound, const char* what,
                                   size_t columns);
// A 1-D integer array, each < bound.
std::vector<uint32_t> read_vector(const AnyArray& a, size_t bound, const char* what);
// (rows, columns) floats of either width; rows must be `rows`.
std::vector<float> read_floats(const AnyArray& a, size_t rows, size_t columns, const char* what);
std::vector<int64_t> signed_indices(const std::vector<uint32_t>& v); // kRemoved -> -1
nb::dict report_dict(const vrs::Report& r, bool bounded, double seconds, double diagonal);

struct Target {
  std::string kind; // "ratio", "faces", "vertices", "bound" (max_error alone)
  double value;
};
vrs::Options make_options(const Target& target, double max_error, const std::string& mode,
                          int threads, bool simplify_boundary, bool keep_boundary, double max_jump,
                          double feature_angle);

template <class T>
nb::ndarray<nb::numpy, T> to_numpy(std::vector<T>&& v, std::initializer_list<size_t> shape) {
  auto* owned = new std::vector<T>(std::move(v));
  nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
  return nb::ndarray<nb::numpy, T>(owned->data(), shape, owner);
}

} // namespace vrs_py
