// The paper's hash table: n intervals, each a FIFO list. A list is an array of vertices read
// from its head and appended at its back; erasing a vertex blanks its entry (its node names
// the slot), and a list is compacted when blanks outnumber its vertices. Reading a batch off
// the front is then a walk along contiguous memory, not a chase through linked vertices
// scattered over the mesh (a tenth of the serial time at 4.8 M faces).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "base/uninitialized.h"
#include "base/workers.h"
#include "mesh/topology.h"
#include "queue/interval_map.h"

namespace vrs {

class BucketQueue {
 public:
  // Empty, for vertices [0, vertex_count); the table is cleared on the workers when given.
  void init(size_t vertex_count, const IntervalMap& map, Workers* workers = nullptr);
  // On an empty queue: every vertex of `blocks` pushed at `factor[v]`, as push() one by one in
  // block order would, with the intervals found and the lists written on the workers (the
  // whole queue's first fill was a serial pass over scattered vertices).
  void fill(const std::vector<std::vector<uint32_t>>& blocks, const float* factor,
            Workers* workers);

  // Appends v at the end of the interval of `factor` (re-evaluated vertices go to the back:
  // this spreads removals over the mesh instead of eating one region).
  void push(uint32_t v, double factor);
  void erase(uint32_t v);
  // A queued vertex's factor changed: it moves to the back of its new interval, or stays where
  // it is when the interval is the same.
  void update(uint32_t v, double factor) {
    const int i = map_.interval_of(factor);
    if (i != int(node_[v].where)) erase(v), link_back(v, i);
  }
  bool contains(uint32_t v) const { return node_[v].where != kNone; }
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  bool only_last_left() const { return size_ > 0 && lowest() == map_.n - 1; }

  // First vertex of the lowest non-empty interval, or kNone. It stays queued until erased.
  uint32_t front() const;
  void prefetch(uint32_t v) const { vrs::prefetch(&node_[v]); }
  // A batch: up to `max` vertices of the lowest interval from its front, into `out`.
  size_t read_front(uint32_t* out, size_t max) const;
  // Interval of a queued vertex.
  int interval(uint32_t v) const { return int(node_[v].where); }
  // Whether a vertex of this factor, pushed now, would be in the lowest non-empty interval or
  // no later than `from` (the interval it was read off): a vertex popped with a stale priority
  // and priced again is removed at once when it is still the cheapest, else pushed back.
  bool still_cheapest(double factor, int from) const {
    return size_ == 0 || map_.interval_of(factor) <= std::max(lowest(), from);
  }

  // Re-maps every queued vertex over [0, max factor of the queue], keeping their order. Used
  // when a count target is not met and only the last interval is left: the bucket order is
  // then no order at all, and a new range restores it. `factor` is indexed by vertex.
  void respread(const float* factor);

  const IntervalMap& map() const { return map_; }

 private:
  int lowest() const;
  void link_back(uint32_t v, int interval);

  IntervalMap map_;
  struct Node {     // no member initializers: the table is written whole on the workers
    uint32_t where; // its interval, kNone when not queued
    uint32_t slot;  // its entry in that interval's list
  };
  static constexpr Node kOut{kNone, kNone};
  struct List {
    std::vector<uint32_t> entries; // vertices in the order appended; kNone: erased
    uint32_t head = 0;             // the first vertex (entries before it are blank)
    uint32_t live = 0;
  };
  void compact(List& l);
  UninitVector<Node> node_;
  std::vector<List> lists_;
  std::vector<uint64_t> nonempty_; // bit i: interval i has vertices
  size_t size_ = 0;
};

} // namespace vrs
