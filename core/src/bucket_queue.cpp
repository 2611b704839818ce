#include "bucket_queue.h"

namespace vrs {

void BucketQueue::init(size_t vertex_count, const IntervalMap& map) {
  map_ = map;
  next_.assign(vertex_count, kNone);
  prev_.assign(vertex_count, kNone);
  where_.assign(vertex_count, kNone);
  head_.assign(map.n, kNone);
  tail_.assign(map.n, kNone);
  nonempty_.assign((map.n + 63) / 64, 0);
  size_ = 0;
}

void BucketQueue::link_back(uint32_t v, int interval) {
  prev_[v] = tail_[interval];
  next_[v] = kNone;
  if (tail_[interval] != kNone)
    next_[tail_[interval]] = v;
  else
    head_[interval] = v;
  tail_[interval] = v;
  where_[v] = static_cast<uint32_t>(interval);
  nonempty_[interval >> 6] |= uint64_t(1) << (interval & 63);
  ++size_;
}

void BucketQueue::push(uint32_t v, double factor) {
  if (contains(v)) erase(v);
  link_back(v, map_.interval_of(factor));
}

void BucketQueue::erase(uint32_t v) {
  uint32_t i = where_[v];
  if (i == kNone) return;
  if (prev_[v] != kNone)
    next_[prev_[v]] = next_[v];
  else
    head_[i] = next_[v];
  if (next_[v] != kNone)
    prev_[next_[v]] = prev_[v];
  else
    tail_[i] = prev_[v];
  if (head_[i] == kNone) nonempty_[i >> 6] &= ~(uint64_t(1) << (i & 63));
  where_[v] = next_[v] = prev_[v] = kNone;
  --size_;
}

int BucketQueue::lowest() const {
  for (size_t w = 0; w < nonempty_.size(); ++w)
    if (nonempty_[w]) return static_cast<int>(w * 64 + __builtin_ctzll(nonempty_[w]));
  return -1;
}

uint32_t BucketQueue::front() const {
  int i = lowest();
  return i < 0 ? kNone : head_[i];
}

void BucketQueue::respread(const float* factor) {
  // Collect in queue order (interval by interval, FIFO inside), then re-append in that order.
  std::vector<uint32_t> order;
  order.reserve(size_);
  double top = 0;
  for (int i = 0; i < map_.n; ++i)
    for (uint32_t v = head_[i]; v != kNone; v = next_[v]) {
      order.push_back(v);
      top = std::max(top, static_cast<double>(factor[v]));
    }
  for (uint32_t v : order)
    erase(v);
  map_.f_max = top;
  for (uint32_t v : order)
    link_back(v, map_.interval_of(factor[v]));
}

} // namespace vrs
