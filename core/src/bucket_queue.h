// The paper's hash table: n intervals, each a FIFO list threaded through the vertices
// (intrusive prev/next, so unlink and append are O(1) and nothing is allocated after init).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "interval_map.h"
#include "topology.h"

namespace vrs {

class BucketQueue {
 public:
  void init(size_t vertex_count, const IntervalMap& map);

  // Appends v at the end of the interval of `factor` (re-evaluated vertices go to the back:
  // this spreads removals over the mesh instead of eating one region).
  void push(uint32_t v, double factor);
  void erase(uint32_t v);
  // A queued vertex's factor changed: it moves to the back of its new interval, or stays where
  // it is when the interval is the same.
  void update(uint32_t v, double factor) {
    const int i = map_.interval_of(factor);
    if (i != int(where_[v])) erase(v), link_back(v, i);
  }
  bool contains(uint32_t v) const { return where_[v] != kNone; }
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  bool only_last_left() const { return size_ > 0 && lowest() == map_.n - 1; }

  // First vertex of the lowest non-empty interval, or kNone. It stays queued until erased.
  uint32_t front() const;
  // The vertex after v in its interval (kNone: v is its last): a batch is read off the front.
  uint32_t after(uint32_t v) const { return next_[v]; }
  // Interval of a queued vertex.
  int interval(uint32_t v) const { return int(where_[v]); }
  // Whether a vertex of this factor, pushed now, would be in the lowest non-empty interval or
  // no later than `from` (the interval it was read off): a vertex popped with a stale priority
  // and priced again is removed at once when it still leads, else pushed back.
  bool leads(double factor, int from) const {
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
  std::vector<uint32_t> next_, prev_, where_;
  std::vector<uint32_t> head_, tail_;
  std::vector<uint64_t> nonempty_; // bit i: interval i has vertices
  size_t size_ = 0;
};

} // namespace vrs
