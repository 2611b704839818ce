// File I/O for the command-line tool, through vcglib's importers and exporters (the same code
// MeshLab uses), and the conversion to and from the core mesh.
#pragma once

#include <string>

#include "vrs/simplify.h"

namespace vrs_tool {

class VcgDocument; // a loaded file: vcglib mesh plus what the file held (mask)

struct LoadResult {
  VcgDocument* doc = nullptr; // owned by the caller: release with close()
  std::string error;
};

LoadResult load(const std::string& path);
void close(VcgDocument* doc);

// Positions and triangles of the document, in file order.
vrs::Mesh to_core(const VcgDocument& doc);

// Applies the result: drops removed vertices (attributes of the kept ones untouched) and
// replaces the faces by the simplified ones.
void apply(VcgDocument& doc, const vrs::Mesh& simplified, const vrs::Report& report);

// Writes with every per-vertex attribute the input had. Empty string on success.
std::string save(VcgDocument& doc, const std::string& path, bool ascii);

} // namespace vrs_tool
