// Exact priority queue (binary min-heap with positions), the reference the hash table is
// measured against. Ties are broken by insertion order, like the FIFO of an interval.
#pragma once

#include <cstdint>
#include <vector>

#include "base/workers.h"
#include "mesh/topology.h"
#include "queue/interval_map.h"

namespace vrs {

class HeapQueue {
 public:
  void init(size_t vertex_count, const IntervalMap& map, Workers* = nullptr);
  // Pushes each vertex of `blocks` in block order (one heap: no parallel fill).
  void fill(const std::vector<std::vector<uint32_t>>& blocks, const float* factor, Workers*) {
    for (const auto& block : blocks)
      for (uint32_t v : block)
        push(v, factor[v]);
  }
  void push(uint32_t v, double factor);
  void erase(uint32_t v);
  void update(uint32_t v, double factor) { push(v, factor); }
  bool contains(uint32_t v) const { return pos_[v] != kNone; }
  size_t size() const { return heap_.size(); }
  bool empty() const { return heap_.empty(); }
  // Same meaning as the hash table's: the smallest factor lies in the last interval.
  bool only_last_left() const {
    return !heap_.empty() && map_.interval_of(heap_[0].factor) == map_.n - 1;
  }
  uint32_t front() const { return heap_.empty() ? kNone : heap_[0].v; }
  // An exact order has no cheap "next": its batches hold the front alone.
  void prefetch(uint32_t) const {}
  size_t read_front(uint32_t* out, size_t max) const {
    if (heap_.empty() || max == 0) return 0;
    out[0] = heap_[0].v;
    return 1;
  }
  int interval(uint32_t) const { return -1; }
  bool still_cheapest(double factor, int) const {
    return heap_.empty() || factor <= heap_[0].factor;
  }
  void respread(const float*) {} // already exact
  const IntervalMap& map() const { return map_; }

 private:
  struct Entry {
    double factor;
    uint64_t seq;
    uint32_t v;
  };
  static bool less(const Entry& a, const Entry& b) {
    return a.factor < b.factor || (a.factor == b.factor && a.seq < b.seq);
  }
  void place(size_t i, const Entry& e);
  void sift_up(size_t i);
  void sift_down(size_t i);

  IntervalMap map_;
  std::vector<Entry> heap_;
  std::vector<uint32_t> pos_;
  uint64_t seq_ = 0;
};

} // namespace vrs
