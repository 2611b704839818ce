// File I/O for the command-line tool, through vcglib's importers and exporters (the same code
// MeshLab uses), and the conversion to and from the core mesh.
#pragma once

#include <string>
#include <vector>

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

// True when the document holds per-corner data (texture coordinates, normals) or face colors,
// which then follow the simplification (ask the core for corner sources).
bool has_corner_data(const VcgDocument& doc);
// True when the vertices hold more than a position (normals, colors, texture coordinates,
// quality, or a PLY vertex property of any other name): copies of one position may then
// differ, and a seam written as split vertices keeps each side's.
bool has_vertex_data(const VcgDocument& doc, const std::string& path);
// True when the faces' corners hold data that can tell two sides of a seam apart: texture
// coordinates, colors, smooth normals (flat shading, one normal a face, cannot).
bool has_seam_data(const VcgDocument& doc);
// Per-corner normals turning more than this make a hard edge (default vrs_vcg::kNormalCreaseDeg).
void set_feature_angle(VcgDocument& doc, double degrees);
// Edges across which that data differs (seams), as core vertex pairs: the core keeps them.
std::vector<uint32_t> seams(const VcgDocument& doc, const vrs::Mesh& core);

// Per core face, whether it is part of one of the file's polygons (OBJ and OFF faces of more
// than three corners; Options::polygon_faces), or empty when the file has none: polygons the
// run leaves whole are written back whole.
std::vector<uint8_t> polygon_faces(const VcgDocument& doc, size_t face_count);

// Applies the result: drops removed vertices (attributes of the kept ones untouched) and
// replaces the faces by the simplified ones, each corner with the per-corner data of the input
// corner the report names (when it has corner sources).
void apply(VcgDocument& doc, const vrs::Mesh& simplified, const vrs::Report& report);

class ExactVertices;

// Writes with every per-vertex, per-corner and per-face attribute the input had (per-corner
// and per-face ones only when apply() could carry them). Empty string on success. With
// `exact` (needed()) and a PLY output, the vertices are the input's records, untouched:
// `kept` names the input vertex of each output vertex.
std::string save(VcgDocument& doc, const std::string& path, bool ascii,
                 const ExactVertices* exact = nullptr, const std::vector<uint32_t>* kept = nullptr);

} // namespace vrs_tool
