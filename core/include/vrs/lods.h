// Nested levels of detail in one run: each level simplified from the one before, so every
// level's vertices are a subset of the finer level's, untouched. All levels can then share one
// vertex array ordered coarsest level first, each level a prefix of it plus its own triangles
// (what a streamed glTF needs: tools/glb_writer.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vrs/simplify.h"

namespace vrs {

struct LodLevel {
  double ratio = 1.0;              // of the input's faces, as asked
  size_t vertex_count = 0;         // this level uses LodChain::vertices[0, vertex_count)
  std::vector<uint32_t> triangles; // into LodChain::vertices
  // For each face: the input face it is, or kRemoved (made by a re-triangulation).
  std::vector<uint32_t> face_source;
  // With corner keys or Options::corner_sources: for each face corner, the input corner
  // (3 * input face + corner) whose per-corner data it takes.
  std::vector<uint32_t> corner_source;
  Report report; // of the run that made this level from the finer one
};

struct LodChain {
  bool ok = false;
  std::string message; // the error when not ok
  // Input vertex ids: the coarsest level's referenced vertices first (in input order), then
  // those the next finer level adds, and so on.
  std::vector<uint32_t> vertices;
  std::vector<LodLevel> levels; // finest first (ratios sorted decreasing)
};

// Simplifies `input` to each ratio in (0, 1] (1: the input itself, cleaned as simplify()
// cleans it), each level from the finer one, with `options` (its target is ignored; a
// `locked` vector and `constrained_edges` are in input numbering and followed through the
// levels). `corner_keys` (optional, one per input corner: equal keys = same per-corner data,
// e.g. texture coordinates) makes every edge across which the keys differ a seam the levels
// keep, and fills corner_source.
LodChain simplify_lods(const Mesh& input, std::vector<double> ratios, const Options& options,
                       const std::vector<uint32_t>* corner_keys = nullptr);

} // namespace vrs
