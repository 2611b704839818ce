#include "workers.h"

#include <algorithm>
#include <chrono>

namespace vrs {

namespace {

// How long an idle thread polls for the next loop before it sleeps. The driver hands out a
// loop every few tens of microseconds (a batch of plans, then its rewrites); a sleeping
// thread takes longer than that to wake, and a loop is over before it is up.
constexpr auto kSpin = std::chrono::microseconds(200);

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

int hardware_threads() {
  return std::max(1, int(std::thread::hardware_concurrency()));
}

Workers::Workers(int threads) : poll_(threads <= hardware_threads()) {
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

void Workers::work() {
  for (;;) {
    size_t first = next_.fetch_add(grain_, std::memory_order_relaxed);
    if (first >= n_) return;
    for (size_t i = first, end = std::min(n_, first + grain_); i < end; ++i)
      (*fn_)(i);
  }
}

void Workers::serve() {
  size_t seen = 0;
  for (;;) {
    // Poll first, then sleep until the generation moves.
    const auto until = std::chrono::steady_clock::now() + kSpin;
    int polls = 0;
    while (poll_ && generation_.load(std::memory_order_acquire) == seen && !quit_.load() &&
           std::chrono::steady_clock::now() < until)
      relax_cpu(polls);
    if (generation_.load(std::memory_order_acquire) == seen) {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return quit_.load() || generation_.load() != seen; });
    }
    if (quit_.load()) return;
    seen = generation_.load(std::memory_order_acquire);
    work();
    if (busy_.fetch_sub(1, std::memory_order_acq_rel) == 1 && !poll_) {
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

void Workers::timed(size_t n, const std::function<void(size_t)>& fn, size_t grain, bool ranges) {
  if (n == 0) return;
  const auto start = std::chrono::steady_clock::now();
  spread(n, fn, grain);
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  parallel_seconds_ += t;
  // The projection's rounds (span_seconds): a range loop has one range a thread at any count.
  const size_t g = std::max<size_t>(1, grain), chunks = (n + g - 1) / g;
  for (int i = 0; i < 2; ++i) {
    const size_t p = size_t(kProjected[i]), c = ranges ? p : chunks;
    span_[i] += t * double((c + p - 1) / p) / double(c);
  }
}

void Workers::spread(size_t n, const std::function<void(size_t)>& fn, size_t grain) {
  if (pool_.empty() || n <= grain) { // not worth waking anyone
    for (size_t i = 0; i < n; ++i)
      fn(i);
    return;
  }
  fn_ = &fn;
  n_ = n;
  grain_ = std::max<size_t>(1, grain);
  next_.store(0, std::memory_order_relaxed);
  busy_.store(int(pool_.size()), std::memory_order_relaxed);
  {
    // Under the lock, so a thread between its last look and its wait cannot miss the wake.
    std::lock_guard<std::mutex> lock(mutex_);
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  work();
  // The others finish their last items; they are running, so poll.
  if (!poll_) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return busy_.load(std::memory_order_acquire) == 0; });
    return;
  }
  int polls = 0;
  while (busy_.load(std::memory_order_acquire) != 0)
    relax_cpu(polls);
}

} // namespace vrs
