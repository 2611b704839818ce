#include "base/workers.h"

#include <algorithm>
#include <chrono>

#include "vrs/simplify.h"

namespace vrs {

namespace {

// How long an idle thread polls for the next loop before it sleeps. The driver hands out a
// loop every few tens of microseconds (a batch of plans, then its rewrites); a sleeping
// thread takes longer than that to wake, and a loop is over before it is up.
constexpr auto kSpin = std::chrono::microseconds(200);
// A thread that came too late to take an item this many loops in a row stops polling and
// sleeps until woken: on a machine busy with other work its polling only takes the core from
// the caller, which does the items alone.
constexpr int kMissesBeforeSleep = 4;
// Loops of at most this many chunks (most batches of plans hold four or fewer) run on the
// caller alone once this many in a row got no help from the pool, but every kProbeEvery-th.
constexpr size_t kFewChunks = 8;
constexpr int kUnhelpedBeforeAlone = 4;
constexpr unsigned kProbeEvery = 32;

// One wait of a polling loop: a pause at first, then the core given up, so that on a machine
// busy with other work the threads with work still get their turn.
inline void relax_cpu(int& polls) {
  if (++polls < 2000) {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  } else {
    std::this_thread::yield();
  }
}

} // namespace

void for_each_on(Workers* workers, size_t n, const std::function<void(size_t)>& fn, size_t grain) {
  if (workers) {
    workers->for_each(n, fn, grain);
    return;
  }
  for (size_t i = 0; i < n; ++i)
    fn(i);
}

void for_each_range_on(Workers* workers, size_t n, const std::function<void(size_t)>& fn) {
  if (workers) {
    workers->for_each_range(n, fn);
    return;
  }
  for (size_t i = 0; i < n; ++i)
    fn(i);
}

void for_each_block(Workers* workers, size_t n, size_t block,
                    const std::function<void(size_t, size_t)>& fn) {
  for_each_on(workers, (n + block - 1) / block,
              [&](size_t b) { fn(b * block, std::min(n, (b + 1) * block)); });
}

Workers::Workers(int threads) : poll_(threads <= usable_cores()) {
  for (int t = 1; t < threads; ++t)
    pool_.emplace_back([this] { serve(); });
}

Workers::~Workers() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    quit_.store(true);
  }
  wake_.notify_all();
  for (auto& t : pool_)
    t.join();
}

bool Workers::work() {
  for (bool took = false;; took = true) {
    size_t first = next_.fetch_add(grain_, std::memory_order_relaxed);
    if (first >= n_) return took;
    for (size_t i = first, end = std::min(n_, first + grain_); i < end; ++i)
      (*fn_)(i);
  }
}

void Workers::serve() {
  size_t seen = 0;
  int misses = 0; // loops in a row this thread joined too late to take an item
  for (;;) {
    // Poll first (unless the last loops were over before this thread came), then sleep
    // until the generation moves.
    const auto until = std::chrono::steady_clock::now() + kSpin;
    int polls = 0;
    while (poll_ && misses < kMissesBeforeSleep &&
           generation_.load(std::memory_order_acquire) == seen && !quit_.load() &&
           std::chrono::steady_clock::now() < until)
      relax_cpu(polls);
    if (generation_.load(std::memory_order_acquire) == seen) {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return quit_.load() || generation_.load() != seen; });
    }
    if (quit_.load()) return;
    seen = generation_.load(std::memory_order_acquire);
    // Join, then look whether the loop still takes helpers: the caller closes it once every
    // item is handed out and waits only for those that joined while it was open, never for a
    // thread the system has not run yet (on a busy machine, one may not run for milliseconds).
    joined_.fetch_add(1);
    const bool took = open_.load() && work();
    misses = took ? 0 : misses + 1;
    if (took) helped_.store(true, std::memory_order_relaxed);
    if (joined_.fetch_sub(1) == 1 && !poll_) {
      std::lock_guard<std::mutex> lock(mutex_); // the caller sleeps: wake it
      done_.notify_one();
    }
  }
}

void Workers::for_each(size_t n, const std::function<void(size_t)>& fn, size_t grain) {
  timed(n, fn, grain, false);
}

void Workers::for_each_range(size_t n, const std::function<void(size_t)>& fn) {
  timed(n, fn, 1, true);
}

namespace {

// A chunk this long or longer is timed on its own: the clock's two reads (tens of ns) are then
// under a thousandth of it. The first chunk decides for its loop; the plans of a batch (a few
// microseconds each) stay with rounds of their mean.
constexpr double kTimedChunk = 50e-6;

// The span of chunks handed out in order to whichever of `threads` is free first.
double list_span(const std::vector<double>& chunks, size_t threads) {
  std::vector<double> free_at(threads, 0.0); // a min-heap (std::greater) of finish times
  for (double t : chunks) {
    std::pop_heap(free_at.begin(), free_at.end(), std::greater<double>());
    free_at.back() += t;
    std::push_heap(free_at.begin(), free_at.end(), std::greater<double>());
  }
  return *std::max_element(free_at.begin(), free_at.end());
}

} // namespace

bool Workers::timed_by_chunks(size_t n, const std::function<void(size_t)>& fn, size_t grain,
                              std::chrono::steady_clock::time_point start) {
  using clock = std::chrono::steady_clock;
  const size_t g = std::max<size_t>(1, grain);
  for (size_t i = 0; i < std::min(n, g); ++i)
    fn(i);
  auto end = clock::now();
  const double first = std::chrono::duration<double>(end - start).count();
  const bool by_chunks = first >= kTimedChunk;
  chunk_seconds_.assign(1, first);
  for (size_t c = g; c < n; c += g) {
    for (size_t i = c; i < std::min(n, c + g); ++i)
      fn(i);
    if (by_chunks) {
      start = end;
      end = clock::now();
      chunk_seconds_.push_back(std::chrono::duration<double>(end - start).count());
    }
  }
  if (!by_chunks) return false;
  for (double c : chunk_seconds_)
    parallel_seconds_ += c;
  for (int i = 0; i < 2; ++i)
    span_[i] += list_span(chunk_seconds_, size_t(kProjected[i]));
  return true;
}

void Workers::timed(size_t n, const std::function<void(size_t)>& fn, size_t grain, bool ranges) {
  if (n == 0) return;
  const auto start = std::chrono::steady_clock::now();
  if (pool_.empty() && !ranges && n > grain) {
    // On one thread (the projection's basis), long chunks are timed one by one.
    if (timed_by_chunks(n, fn, grain, start)) return;
  } else {
    spread(n, fn, grain);
  }
  add_rounds(n, grain, ranges,
             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

void Workers::add_rounds(size_t n, size_t grain, bool ranges, double t) {
  parallel_seconds_ += t;
  // The projection's rounds (span_seconds): a range loop has one range a thread at any count.
  const size_t g = std::max<size_t>(1, grain), chunks = (n + g - 1) / g;
  for (int i = 0; i < 2; ++i) {
    const size_t p = size_t(kProjected[i]), c = ranges ? p : chunks;
    span_[i] += t * double((c + p - 1) / p) / double(c);
  }
}

void Workers::spread(size_t n, const std::function<void(size_t)>& fn, size_t grain) {
  // Not worth waking anyone: one chunk; or a loop of a few chunks while the last such loops
  // got no help (the other cores busy with other work, or the loops over before a thread
  // woke), except every kProbeEvery-th, which looks again.
  const bool few = n <= kFewChunks * std::max<size_t>(1, grain);
  if (pool_.empty() || n <= grain ||
      (few && unhelped_ >= kUnhelpedBeforeAlone && ++alone_ % kProbeEvery != 0)) {
    for (size_t i = 0; i < n; ++i)
      fn(i);
    return;
  }
  helped_.store(false, std::memory_order_relaxed);
  fn_ = &fn;
  n_ = n;
  grain_ = std::max<size_t>(1, grain);
  next_.store(0, std::memory_order_relaxed);
  open_.store(true);
  {
    // Under the lock, so a thread between its last look and its wait cannot miss the wake.
    std::lock_guard<std::mutex> lock(mutex_);
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  work();
  // Every item is handed out: no one joins any more. Those that did finish their last items;
  // they are running, so poll.
  open_.store(false);
  if (!poll_) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return joined_.load() == 0; });
    note_help(few);
    return;
  }
  int polls = 0;
  while (joined_.load() != 0)
    relax_cpu(polls);
  note_help(few);
}

void Workers::note_help(bool few) {
  if (few) unhelped_ = helped_.load(std::memory_order_relaxed) ? 0 : unhelped_ + 1;
}

} // namespace vrs
