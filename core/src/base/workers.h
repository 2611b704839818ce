// A fixed set of threads that run one loop at a time (fork-join). The simplifier hands it the
// read-only work of a batch (planning independent removals, pricing neighbours); whoever
// computes item i, its result goes to slot i, so the output does not depend on the threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <limits>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "base/uninitialized.h"

namespace vrs {

class Workers {
 public:
  // `threads` in total, the caller's included (1: everything runs on the caller).
  explicit Workers(int threads);
  ~Workers();
  Workers(const Workers&) = delete;
  Workers& operator=(const Workers&) = delete;

  int threads() const { return int(pool_.size()) + 1; }

  // Calls fn(i) for every i in [0, n) and returns when all calls are done. Items are handed
  // out `grain` at a time to whichever thread is free.
  void for_each(size_t n, const std::function<void(size_t)>& fn, size_t grain = 4);
  // The same over `n` ranges, one a thread (range_of): a loop that divides by the threads
  // whatever their number.
  void for_each_range(size_t n, const std::function<void(size_t)>& fn);
  // Wall time spent in for_each so far: the work spread over the threads (the rest of a run
  // is its serial part, the base of Amdahl's projection in bench/SPEED.md).
  double parallel_seconds() const { return parallel_seconds_; }
  // What those loops would take on 8 (16) threads, from a run on one: each loop's time over
  // its chunks (grain items, or one range a thread), ceil(chunks / threads) rounds of the
  // mean chunk. A loop of one chunk runs on one thread at any count, and a loop of 20 chunks
  // takes two rounds on 16 (Amdahl's split into "serial" and "even" misses both). A loop of
  // long chunks (the parts) is timed chunk by chunk and its chunks handed out in order to
  // whichever of the threads is free first, as for_each does: uneven chunks take longer than
  // rounds of their mean, and a long one handed out last leaves the others idle.
  // Projected for kProjected's counts only (NaN for any other).
  static constexpr int kProjected[2] = {8, 16};
  double span_seconds(int threads) const {
    for (int i = 0; i < 2; ++i)
      if (threads == kProjected[i]) return span_[i];
    return std::numeric_limits<double>::quiet_NaN();
  }

 private:
  void serve();
  bool work(); // the current loop's items until none is left; false: it took none

  std::vector<std::thread> pool_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  // Whether waits poll first: only when every thread has a core of its own (with more threads
  // than cores a polling thread takes the core from one with work).
  bool poll_ = false;
  const std::function<void(size_t)>* fn_ = nullptr;
  size_t n_ = 0, grain_ = 1;
  std::atomic<size_t> next_{0};
  std::atomic<size_t> generation_{0}; // one more per loop handed out
  // Threads of the pool that joined the current loop (and may hold items of it); it takes
  // helpers only while open_, until its last item is handed out.
  std::atomic<int> joined_{0};
  std::atomic<bool> open_{false};
  // Whether a pool thread took an item of the current loop; the caller's count of loops of a
  // few chunks in a row that got no help, and of those it then ran alone.
  std::atomic<bool> helped_{false};
  int unhelped_ = 0;
  unsigned alone_ = 0;
  void note_help(bool few);
  std::atomic<bool> quit_{false};
  double parallel_seconds_ = 0;
  double span_[2] = {0, 0};           // span_seconds(kProjected[i])
  std::vector<double> chunk_seconds_; // a timed loop's chunks, on one thread
  void timed(size_t n, const std::function<void(size_t)>& fn, size_t grain, bool ranges);
  // Runs the loop on the caller; when its first chunk is long, adds its time chunk by chunk
  // and returns true (else the caller adds it in rounds of the mean chunk).
  bool timed_by_chunks(size_t n, const std::function<void(size_t)>& fn, size_t grain,
                       std::chrono::steady_clock::time_point start);
  void add_rounds(size_t n, size_t grain, bool ranges, double seconds);
  void spread(size_t n, const std::function<void(size_t)>& fn, size_t grain);
};

// workers->for_each(n, fn, grain) when given, else every fn(i) on the caller (set-up steps
// that also run without a pool).
void for_each_on(Workers* workers, size_t n, const std::function<void(size_t)>& fn,
                 size_t grain = 1);
// workers->for_each_range(n, fn) when given, else every fn(i) on the caller.
void for_each_range_on(Workers* workers, size_t n, const std::function<void(size_t)>& fn);

// fn(begin, end) over [0, n) in blocks of `block` indices (the last one shorter), handed out
// with for_each_on: a block is one item.
void for_each_block(Workers* workers, size_t n, size_t block,
                    const std::function<void(size_t, size_t)>& fn);

// Ranges of [0, n) one a thread (1 without workers), for loops whose threads each read all
// of an input and write only their own range: range r is [first, second).
inline size_t range_count(const Workers* workers) {
  return workers ? size_t(workers->threads()) : 1;
}
inline std::pair<size_t, size_t> range_of(size_t r, size_t ranges, size_t n) {
  const size_t per = (n + ranges - 1) / ranges;
  return {std::min(n, r * per), std::min(n, (r + 1) * per)};
}

// v holds n copies of x, written block by block on the workers (null: on the caller).
template <class T> void fill_on(Workers* workers, UninitVector<T>& v, size_t n, const T& x) {
  v.resize(n);
  for_each_block(workers, n, 65536, [&](size_t begin, size_t end) {
    std::fill(v.begin() + begin, v.begin() + end, x);
  });
}

} // namespace vrs
