// Reads any mesh file for the sweep: the CLI's readers for PLY/OFF/OBJ/STL, assimp otherwise.
#pragma once

#include <string>
#include <vector>

#include "vrs/simplify.h"

namespace vrs_sweep {

// "" on success, else why the file is not a mesh we can test (not a model format, unreadable,
// no triangles).
// `seams` gets the edges across which the file's per-corner data (texture coordinates,
// normals) or face colors differ (PLY/OFF/OBJ/STL; assimp's formats give none).
std::string read_mesh(const std::string& path, vrs::Mesh& out, std::vector<uint32_t>& seams);

} // namespace vrs_sweep
