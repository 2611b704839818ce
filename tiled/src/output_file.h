// The tiled run's output, joined by input vertex id and written in the input's own format: the
// input is streamed a second time and each vertex it still uses is copied as the file holds it
// (every property, in its own type and precision: bit for bit), and each face is written with
// the per-corner data and face properties its keys name. OBJ: the used vt and vn lines, the
// materials by usemtl, the mtllib reference valid from the output's folder.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "output_polygons.h"
#include "partition.h"

namespace vrs::tiled {

// "ply", "obj", "off" by the extension (any case), else "".
std::string format_of(const std::string& path);

// Writes `output` atomically; returns its face count (triangles). `materials`: an OBJ's names
// by group - 1. `flat_normals` (OBJ): the input's vn lines are one a face (flat shading); each
// output face is given its own unit normal instead, as the in-core run gives it. `polygons`
// (OBJ, OFF; may be null): the input's polygons the output holds whole, each written as one
// face where its first triangle comes.
uint64_t write_output(const std::string& input, const std::string& output, uint64_t vertices,
                      uint64_t texcoords, uint64_t normals, bool flat_normals,
                      const std::vector<std::string>& materials, const FaceSource& faces,
                      const OutputPolygons* polygons = nullptr);

} // namespace vrs::tiled
