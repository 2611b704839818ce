// Reads a mesh file as a stream, never whole: each vertex and each triangle is handed to the
// caller as it is read (polygons fanned into triangles), so a file larger than memory passes
// through in constant memory. PLY (ascii, binary little- and big-endian), OBJ and ascii OFF.
//
// Beside the positions it hands over what the output needs to carry every attribute: each
// vertex as the file holds it (copied untouched to the output, whatever its properties and
// precision) and each corner's per-corner data as keys (see CornerKeys).
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace vrs::tiled {

// What one triangle's corners carry, as keys that compare equal when the data is the same:
// a tile tells seams by them (an edge whose two faces disagree at an end), the output writes
// them back. OBJ: a = the corner's vt index + 1, b = its vn index + 1 (0: none), group = its
// material (usemtl, by order of first use, + 1). PLY: a and b = the bits of the corner's
// texcoord u and v (float), group = the face's other properties, packed (at most 4 bytes).
struct CornerKeys {
  uint32_t a[3] = {0, 0, 0}, b[3] = {0, 0, 0};
  uint32_t group = 0;
};
static_assert(sizeof(CornerKeys) == 28, "keys are written as they are");

// The file's layout, as far as an output in the same format must repeat it.
struct Layout {
  enum class Format { Ply, Obj, Off } format = Format::Ply;
  // PLY: the header's format line ("format binary_little_endian 1.0") and the vertex
  // element's property lines, verbatim; the face's texcoord list ("" when none) and its other
  // properties' lines (packed into CornerKeys::group, in this order).
  std::string ply_format;
  std::vector<std::string> vertex_properties;
  std::string texcoord;
  std::vector<std::string> face_properties;
  // OFF: its first keyword (OFF, COFF, NOFF, ...).
  std::string off_keyword;
};

struct StreamSink {
  std::function<void(const double xyz[3])> vertex; // as read, in double
  // Indices as the file gives them, 0-based (OBJ's relative indices resolved); range checks
  // are the caller's, who knows the final vertex count.
  std::function<void(const int64_t v[3], const CornerKeys& keys)> triangle;
  // Optional: once the header is read (OBJ: at the start).
  std::function<void(const Layout&)> layout;
  // Optional: each vertex as the file holds it: a binary PLY's record bytes, an ascii PLY's
  // or OFF's values as written (space-separated), an OBJ's `v` line.
  std::function<void(const char* data, size_t size)> raw_vertex;
  // Optional, OBJ: every line that is neither `v` nor `f` (vt, vn, mtllib, usemtl, ...).
  std::function<void(const std::string& line)> other_line;
  // Optional, OBJ: a material's group number (CornerKeys::group) when it is first used.
  std::function<void(uint32_t group, const std::string& name)> material;
  // Optional: something the file holds that CornerKeys cannot carry (a PLY face property of
  // more than 4 bytes, an extra element, OFF face colors), once, when first seen.
  std::function<void(const std::string& what)> uncarried;
  // Optional: before the triangles of each face of more than three corners, its corner count
  // (the face is fanned from its first corner: corners - 2 triangles follow).
  std::function<void(size_t corners)> polygon;
  // Stop once the vertices are read (a PLY's or OFF's vertices come first; OBJ reads on).
  bool vertices_only = false;
};

// "" on success, else what is wrong and where ("line 12: bad vertex", "truncated file").
// `name` tells the format by its extension (.ply, .obj, .off).
std::string read_mesh_stream(std::FILE* in, const std::string& name, const StreamSink& sink);

} // namespace vrs::tiled
