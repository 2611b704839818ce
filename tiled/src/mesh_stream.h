// Reads a mesh file as a stream, never whole: each vertex and each triangle is handed to the
// caller as it is read (polygons fanned into triangles), so a file larger than memory passes
// through in constant memory. PLY (ascii, binary little- and big-endian), OBJ (v and f) and
// ascii OFF.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>

namespace vrs::tiled {

struct StreamSink {
  std::function<void(const float xyz[3])> vertex;
  // Indices as the file gives them, 0-based (OBJ's relative indices resolved); range checks
  // are the caller's, who knows the final vertex count.
  std::function<void(const int64_t v[3])> triangle;
};

// "" on success, else what is wrong and where ("line 12: bad vertex", "truncated file").
// `name` tells the format by its extension (.ply, .obj, .off).
std::string read_mesh_stream(std::FILE* in, const std::string& name, const StreamSink& sink);

} // namespace vrs::tiled
