// Seams written as split vertices (meshes exported for rendering: a copy of the vertex on each
// side of a texture seam or a flat-shading crease, or a soup of faces each with its own three):
// two border edges at the same two positions are one edge of the surface. Welded for the run,
// so that the surface simplifies as the surface it is, and split again on output, each face
// corner taking the copy its input corner had (Options::split_vertices).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vrs {

class Workers;

struct Welding {
  // Input vertex -> the copy that stands for it (the lowest index of its welded set; itself
  // when alone). Empty: nothing welded (then the rest is empty too).
  std::vector<uint32_t> rep;
  // Pairs of standing copies: the welded edges across which the two faces had different
  // copies at an end (the seams that Seam mode constrains).
  std::vector<uint32_t> seams;
  std::vector<uint32_t> corners; // the input's triangles, as given (each corner's own copy)
  size_t welded = 0;             // input vertices standing in another's place
  // Welded edges both faces walk the same way: pieces written in different orientations,
  // which the run turns to agree and the output gives back (orientation.h turned_by_welding).
  size_t same_way = 0;
};

// Welds the vertices of `tris` whose border edges pair up with another's at the same two
// positions, walked either way (bit-for-bit equal coordinates; an edge position held by more
// than two border edges is left alone), unless a face would then hold one vertex twice or an
// edge get a third face. Rewrites `tris` to the standing copies. Costs one hash of the
// referenced positions when nothing is split (on the workers when given).
Welding weld_split_vertices(std::vector<uint32_t>& tris, const std::vector<float>& positions,
                            Workers* workers = nullptr);

} // namespace vrs
