// Reads any mesh file for the sweep: the CLI's readers for PLY/OFF/OBJ/STL, assimp otherwise.
#pragma once

#include <string>

#include "vrs/simplify.h"

namespace vrs_sweep {

// "" on success, else why the file is not a mesh we can test (not a model format, unreadable,
// no triangles).
std::string read_mesh(const std::string& path, vrs::Mesh& out);

} // namespace vrs_sweep
