// Batches: removals read together off the queue's front, planned on the workers against the
// mesh as it is, then taken in queue order as if popped alone. A plan holds only while no
// removal committed before it in the batch touched a vertex in or next to its own.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "driver/vertex_flags.h"
#include "fill/triangulation.h"
#include "mesh/topology.h"

namespace vrs {

// Removals planned together. A constant, not the thread count: the output must not depend on
// it.
constexpr size_t kBatch = 128;

// One removal read off the queue's front and planned (on the workers).
struct Planned {
  std::array<std::pair<uint32_t, uint32_t>, 3 * kMaxRing> overflow; // (vertex, face) to add
  int overflows = 0;
  uint32_t v;
  int from; // the interval it was read off
  // A stale price planned above this is pushed back: not asked the mesh's vetoes (Planner::plan).
  double lead = std::numeric_limits<double>::infinity();
  bool stale, usable;
  bool deferred = false; // it waited for the input's hierarchy (InputSurface::Deferral)
  Reject why;
  double priority;
  Ring ring;
  Patch patch;
  // With lazy re-pricing, how the removal changes each ring vertex's fan area
  // (fan_area_changes): made with the plan, on the workers, for the accounting.
  std::array<double, kMaxRing + 1> area_change;
};

// Reads up to `ids.size()` vertices off the front of the queue's lowest interval into `ids`
// (a small array: the batch's plans are kilobytes each, written by the workers); `from` is the
// interval. From the lowest interval only: reaching further up filled the batches but cost
// error on the whole data set.
template <class Queue>
size_t take_front(const Queue& queue, std::vector<uint32_t>& ids, int& from) {
  const size_t count = queue.read_front(ids.data(), ids.size());
  from = count ? queue.interval(ids[0]) : -1;
  return count;
}

// The vertices the removals committed so far in a batch touched (each one's closed
// neighbourhood), as kFlagTaken in the driver's flags.
class TakenMarks {
 public:
  // Whether a plan made before the batch's commits still holds: no mark on v nor its ring.
  bool holds(const std::vector<uint8_t>& flags, uint32_t v, const Ring& ring) const;
  void mark(std::vector<uint8_t>& flags, uint32_t v, const Ring& ring);
  void clear(std::vector<uint8_t>& flags); // for the next batch

 private:
  std::vector<uint32_t> marked_;
};

} // namespace vrs
