#include "workers.h"

#include <algorithm>

namespace vrs {

int hardware_threads() {
  return std::max(1, int(std::thread::hardware_concurrency()));
}

Workers::Workers(int threads) {
  for (int t = 1; t < threads; ++t)
    pool_.emplace_back([this] { serve(); });
}

Workers::~Workers() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    quit_ = true;
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
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return quit_ || generation_ != seen; });
      if (quit_) return;
      seen = generation_;
    }
    work();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (--busy_ == 0) done_.notify_one();
    }
  }
}

void Workers::for_each(size_t n, const std::function<void(size_t)>& fn, size_t grain) {
  if (n == 0) return;
  if (pool_.empty() || n <= grain) { // not worth waking anyone
    for (size_t i = 0; i < n; ++i)
      fn(i);
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    fn_ = &fn;
    n_ = n;
    grain_ = std::max<size_t>(1, grain);
    next_.store(0, std::memory_order_relaxed);
    busy_ = int(pool_.size());
    ++generation_;
  }
  wake_.notify_all();
  work();
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [&] { return busy_ == 0; });
}

} // namespace vrs
