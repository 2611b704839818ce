// Refuses what cannot be simplified meaningfully, before anything is touched.
#pragma once

#include <string>

#include "vrs/simplify.h"

namespace vrs {

// Empty when fine, else a message naming the first problem.
std::string check_options(const Options& options, size_t vertex_count, size_t face_count);
std::string check_mesh(const Mesh& mesh);

} // namespace vrs
