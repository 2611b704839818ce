// Levels of detail in one binary glTF 2.0 file (.glb), made to be streamed: one vertex buffer
// shared by every level, ordered coarsest level first (each level draws a prefix of it), one
// index buffer per level, the levels bound by MSFT_lod on the finest level's node.
//
// Binary chunk, in order: the coarsest level's indices, the shared vertices (interleaved:
// position, normal, color, texture coordinates, as the input has them), then each finer
// level's indices, coarsest first. So the first bytes of the file draw the coarsest level
// (its indices, then its prefix of the vertices), and a reader with HTTP range requests
// draws level L from the vertex prefix [0, its vertex count) and its own indices. A layout
// where every prefix of the file holds whole levels is not expressible in glTF 2.0: each
// level's vertex accessor must be one contiguous range, so no index data can lie between
// a coarser level's vertices and the vertices a finer level adds.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "vrs/lods.h"
#include "vrs/progressive.h"

namespace vrs {

struct GlbAttributes {
  // Per input vertex, or nullptr.
  const float* normals = nullptr; // 3 a vertex (normalized on write)
  const float* colors = nullptr;  // 4 a vertex, RGBA in [0, 1]
  const float* uvs = nullptr;     // 2 a vertex, (0, 0) at the image's bottom left (OBJ, PLY)
  // Per input corner (3 * face + corner), or nullptr: these take precedence over the
  // per-vertex ones; a vertex whose corners differ becomes one glTF vertex per distinct
  // corner (a seam). Needs the chain's corner_source (simplify_lods with corner keys).
  const float* corner_normals = nullptr;
  const float* corner_colors = nullptr;
  const float* corner_uvs = nullptr;
  // The base color image, as a URI relative to the .glb ("" for none).
  std::string texture_uri;
  // Per level (finest first, as the chain's levels), an error to record in the mesh's extras,
  // e.g. a certified bound in mesh units; empty or negative: none.
  std::vector<double> level_errors;
  std::string generator = "vrsimplify";
  // EXT_meshopt_compression (meshoptimizer's codec, lossless: positions stay the input's
  // floats), required by the file then; three.js, Babylon.js and gltfpack read it. Streaming
  // survives: each level's vertices end on a block of the vertex codec (a few copies of its
  // last vertex pad it), so the stream's first bytes decode the coarser levels alone.
  bool compress = false;
};

// What was written, for the caller's report and for tests.
struct GlbLayout {
  size_t file_bytes = 0;
  size_t vertex_count = 0; // glTF vertices (input vertices, split at seams)
  size_t vertex_stride = 0;
  bool compressed = false;
  struct Level {
    size_t vertex_count = 0, faces = 0;
    size_t index_offset = 0, index_bytes = 0; // in the file
    size_t vertex_bytes = 0;  // its prefix of the vertex buffer (compressed: of the stream)
    size_t bytes_to_draw = 0; // JSON + coarser indices... : the file bytes it needs (see above)
  };
  size_t vertex_offset = 0;  // in the file
  std::vector<Level> levels; // finest first
};

// Writes `chain` (of the mesh with `positions`, 3 floats an input vertex) to `path`, whole or
// not at all (a temporary file renamed). Empty string on success, else the error.
std::string write_glb(const std::string& path, const float* positions, size_t vertex_count,
                      const LodChain& chain, const GlbAttributes& attributes,
                      GlbLayout* layout = nullptr);

// A progressive mesh (vrs/progressive.h) as one .glb (docs/progressive.md specifies it): the
// default scene draws the base mesh, which any glTF reader shows; the primitive's
// VRS_mesh_progressive extension names a buffer view of insertion records, coarsest first,
// each holding the glTF vertices it adds and the faces it writes. The binary chunk: the
// base's indices, its vertices, then the records, so that every prefix of the file draws the
// base and the records it holds whole.
struct ProgressiveLayout {
  size_t file_bytes = 0;
  size_t base_bytes = 0; // the file's bytes up to the base mesh's last vertex
  size_t base_vertices = 0, base_faces = 0;
  size_t vertex_count = 0, faces = 0; // after every insertion
  size_t insertions = 0;
  size_t vertex_stride = 0;
  size_t stream_offset = 0, stream_bytes = 0; // the records, in the file
  // Bytes of the records beyond the vertices they carry (what the faces cost).
  size_t record_topology_bytes = 0;
};

// Writes `p`, made from the mesh with `positions` (3 floats an input vertex) and
// `input_triangles` (the input's faces, which the record's corners name), to `path`, whole or
// not at all. Per-corner attributes need no more than the corners the record holds.
// `attributes.compress` is not supported here. Empty string on success, else the error.
std::string write_progressive_glb(const std::string& path, const float* positions,
                                  size_t vertex_count, const std::vector<uint32_t>& input_triangles,
                                  const ProgressiveMesh& p, const GlbAttributes& attributes,
                                  ProgressiveLayout* layout = nullptr);

} // namespace vrs
