// Simplification by parts: the mesh cut into parts along its spatial order, each part
// simplified on its own queue by one thread, all up to one shared price, while the vertices
// within two edges of another part stay frozen; the whole mesh's queue then finishes the run
// (Franc & Skala, "Parallel triangular mesh decimation without sorting", 2001, cut by space
// too). A removal touches its vertex's ring only, and no frozen vertex's ring changes, so
// parts read and write disjoint memory: the output does not depend on the threads.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/topology.h"

namespace vrs {

class Workers;

// Parts of Tuning::part_vertices vertices, consecutive in the spatial order (which follows
// a Z-order curve): an option, not the thread count, so that the output does not depend on it.
// A second cut shifted by half a part puts the first one's borders inside parts.
struct Parts {
  uint32_t size = 0, shift = 0; // vertices a part; the first part is `shift` shorter
  size_t count = 0;
  // Per vertex: nonzero when within two edges of another part's vertex (its ring may hold
  // another part's vertices, or a neighbour's does): kept while the parts run.
  std::vector<uint8_t> frozen;
  size_t of(uint32_t v) const { return (size_t(v) + shift) / size; }
  uint32_t first(size_t part) const { return uint32_t(part ? part * size - shift : 0); }
  uint32_t end(size_t part, size_t vertex_count) const {
    return uint32_t(std::min(vertex_count, (part + 1) * size - shift));
  }
};

// `topo` lists the live faces of `tris` (in the spatial order). Vertices with a `sibling`
// (fan_split.h; empty: none) stay frozen with their neighbours: an edge test at one reads
// another's lists, which may lie in another part. Vertex by vertex on the workers when given.
Parts make_parts(const std::vector<uint32_t>& tris, const Topology& topo, uint32_t size,
                 uint32_t shift, const std::vector<uint32_t>& sibling = {},
                 Workers* workers = nullptr);

// A part's own queue: an exact (4-ary) heap over the part's range of vertices, 12 bytes an entry
// (the whole mesh's hash table spans all vertices: one a part would cost parts x vertices).
// Ties go by insertion order.
class PartQueue {
 public:
  void init(uint32_t first, size_t count);
  void push(uint32_t v, double f);
  void update(uint32_t v, double f) { push(v, f); }
  void erase(uint32_t v);
  bool contains(uint32_t v) const { return pos_[v - first_] != kNone; }
  bool empty() const { return heap_.empty(); }
  uint32_t front() const { return heap_[0].v + first_; }
  double front_factor() const { return heap_[0].f; }
  size_t count_at_most(double f) const; // entries priced f or less

 private:
  struct Entry {
    float f;
    uint32_t seq, v; // v: in the part
  };
  static bool less(const Entry& a, const Entry& b) {
    return a.f < b.f || (a.f == b.f && a.seq < b.seq);
  }
  void place(size_t i, const Entry& e) {
    heap_[i] = e;
    pos_[e.v] = uint32_t(i);
  }
  void sift_up(size_t i);
  void sift_down(size_t i);

  std::vector<Entry> heap_;
  std::vector<uint32_t> pos_;
  uint32_t first_ = 0, seq_ = 0;
};

} // namespace vrs
