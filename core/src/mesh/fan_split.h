// Vertices where several fans of faces meet and nothing else: cracked exports (bands of faces
// that touch only at points, as in CGAL's pig.stl: 421 such vertices of 8 642), two cones at
// their apexes. The ring walk keeps them (a ring is one fan), and the rest of the mesh thins
// out around rows of kept points. Given one copy a fan for the run, each fan simplifies as the
// surface it is; the copies that stay are one vertex again on output (Simplifier::compact).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/topology.h"

namespace vrs {

struct FanSplit {
  std::vector<uint32_t> original; // the run's vertex n + i is a copy of vertex original[i]
  // Per vertex of the run (copies included): the next of its group, cyclic; kNone when alone.
  // Empty: nothing split.
  std::vector<uint32_t> sibling;
  bool empty() const { return original.empty(); }
};

// For each of `candidates` (ascending: vertices the ring walk kept, non-manifold or of high
// valence; those of more than 4 kMaxRing faces are left whole) whose faces form k > 1 fans,
// each a chain or a cycle of faces that share edges at v: the faces of fans 2..k renamed to
// k - 1 new vertices n, n + 1, ... (`topo`: the lists of `tris` as given; it is not updated). A
// candidate with an edge of more than two faces, or two faces walking one edge the same way, stays
// as it is (kept). Fans of one vertex never share a neighbour (they would share that edge, and be
// one fan), which Topology::has_edge keeps true (siblings).
FanSplit split_fans(std::vector<uint32_t>& tris, size_t n, const Topology& topo,
                    const std::vector<uint32_t>& candidates);

} // namespace vrs
