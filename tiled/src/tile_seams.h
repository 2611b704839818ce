// The seams of a tile: edges across which the per-corner data of the input differs (a UV
// chart's border, a hard normal, a material border). The tile constrains them in the core, as
// the in-core run constrains the seams it finds, so every output corner keeps the data of an
// input corner of its chart.
#pragma once

#include <cstdint>
#include <vector>

#include "vrs/simplify.h"

namespace vrs::tiled {

class CornerValues;

// Each face's three corners' keys (a, b: 3 a face) and its group, beside `mesh`'s triangles;
// and, for an OBJ, the values its vt and vn lines hold (corners then agree by value).
struct TileKeys {
  std::vector<uint32_t> a, b, group;
  std::vector<uint8_t> seam_sides; // per face (FaceRecord::seam_sides); empty: none
  const CornerValues* texcoords = nullptr;
  const CornerValues* normals = nullptr;
};

// Smooth normals turning more than this apart make a hard edge (a seam), as in the CLI
// (vrs_vcg::kNormalCreaseDeg).
constexpr double kNormalCreaseCos = 0.5; // cos 60 degrees

// Vertex pairs (a0, b0, a1, b1, ...) of the edges whose two faces disagree at either end or
// differ in group, or that a face's seam_sides names, for Options::constrained_edges.
std::vector<uint32_t> tile_seams(const vrs::Mesh& mesh, const TileKeys& keys);

} // namespace vrs::tiled
