// Constrained edges: polylines the simplification keeps (texture and normal seams, material
// borders, creases). Which vertices they keep and along which edges a vertex may go; the
// removal along them is planned in removal.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "base/flat_edge_set.h"
#include "mesh/topology.h"
#include "vrs/simplify.h"

namespace vrs {

class Constraints {
 public:
  // The caller's pairs that are edges of the mesh, plus (feature_angle_deg > 0) every edge of
  // two faces whose normals turn further apart. Returns the number of constrained edges.
  size_t build(const Options& o, const float* positions, const std::vector<uint32_t>& tris,
               const Topology& topo, size_t vertex_count);

  // Number of constrained edges at v (saturates at 255).
  int degree(uint32_t v) const { return degree_.empty() ? 0 : degree_[v]; }
  bool active() const { return !degree_.empty(); } // built: edges given or a feature angle
  bool has(uint32_t a, uint32_t b) const { return edges_.contains(a, b); }

  // For a vertex on exactly two constrained edges: their ring positions (i < j). False when
  // they are not both on v's closed ring.
  bool seam_of(uint32_t v, const Ring& ring, int& i, int& j) const;

  // v was removed along its seam (a, v, b): the two edges become (a, b).
  void merge(uint32_t v, uint32_t a, uint32_t b);

 private:
  void add(uint32_t a, uint32_t b);

  std::vector<uint8_t> degree_;
  FlatEdgeSet edges_;
};

} // namespace vrs
