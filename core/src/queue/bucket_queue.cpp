#include "queue/bucket_queue.h"

#include <utility>

namespace vrs {

void BucketQueue::init(size_t vertex_count, const IntervalMap& map, Workers* workers) {
  map_ = map;
  fill_on(workers, node_, vertex_count, kOut);
  lists_.assign(map.n, List{});
  nonempty_.assign((map.n + 63) / 64, 0);
  size_ = 0;
}

void BucketQueue::fill(const std::vector<std::vector<uint32_t>>& blocks, const float* factor,
                       Workers* workers) {
  // Each block's vertices counted by interval, then placed: interval i's list is block 0's
  // vertices of interval i, then block 1's, ... in their order, as pushes in that order.
  const size_t n = lists_.size();
  std::vector<std::vector<uint32_t>> at(blocks.size()); // per block: its first slot in each list
  std::vector<std::vector<uint32_t>> interval(blocks.size()); // per block: each vertex's
  for_each_on(workers, blocks.size(), [&](size_t b) {
    at[b].assign(n, 0);
    interval[b].resize(blocks[b].size());
    for (size_t j = 0; j < blocks[b].size(); ++j)
      ++at[b][interval[b][j] = uint32_t(map_.interval_of(factor[blocks[b][j]]))];
  });
  for (size_t i = 0; i < n; ++i) {
    uint32_t slot = 0;
    for (auto& counts : at)
      slot += std::exchange(counts[i], slot);
    lists_[i].entries.resize(slot);
    lists_[i].live = slot;
    size_ += slot;
    if (slot) nonempty_[i >> 6] |= uint64_t(1) << (i & 63);
  }
  for_each_on(workers, blocks.size(), [&](size_t b) {
    for (size_t j = 0; j < blocks[b].size(); ++j) {
      const uint32_t v = blocks[b][j], i = interval[b][j], slot = at[b][i]++;
      lists_[i].entries[slot] = v;
      node_[v] = {i, slot};
    }
  });
}

void BucketQueue::link_back(uint32_t v, int interval) {
  List& l = lists_[interval];
  node_[v] = {uint32_t(interval), uint32_t(l.entries.size())};
  l.entries.push_back(v);
  ++l.live;
  nonempty_[interval >> 6] |= uint64_t(1) << (interval & 63);
  ++size_;
}

void BucketQueue::push(uint32_t v, double factor) {
  if (contains(v)) erase(v);
  link_back(v, map_.interval_of(factor));
}

void BucketQueue::erase(uint32_t v) {
  const uint32_t i = node_[v].where;
  if (i == kNone) return;
  List& l = lists_[i];
  l.entries[node_[v].slot] = kNone;
  node_[v] = kOut;
  --size_;
  if (--l.live == 0) {
    l.entries.clear(); // the capacity stays: no allocation in the steady state
    l.head = 0;
    nonempty_[i >> 6] &= ~(uint64_t(1) << (i & 63));
    return;
  }
  while (l.entries[l.head] == kNone) // the head stays on a vertex
    ++l.head;
  // Amortized O(1) an erase: blanks are swept once they fill half the list.
  if (l.entries.size() > 2 * size_t(l.live) + 64) compact(l);
}

void BucketQueue::compact(List& l) {
  uint32_t out = 0;
  for (uint32_t i = l.head; i < l.entries.size(); ++i)
    if (l.entries[i] != kNone) {
      node_[l.entries[i]].slot = out;
      l.entries[out++] = l.entries[i];
    }
  l.entries.resize(out);
  l.head = 0;
}

size_t BucketQueue::read_front(uint32_t* out, size_t max) const {
  const int i = lowest();
  if (i < 0) return 0;
  const List& l = lists_[i];
  size_t count = 0;
  for (uint32_t j = l.head; j < l.entries.size() && count < max; ++j)
    if (l.entries[j] != kNone) out[count++] = l.entries[j];
  return count;
}

int BucketQueue::lowest() const {
  for (size_t w = 0; w < nonempty_.size(); ++w)
    if (nonempty_[w]) return static_cast<int>(w * 64 + __builtin_ctzll(nonempty_[w]));
  return -1;
}

uint32_t BucketQueue::front() const {
  const int i = lowest();
  return i < 0 ? kNone : lists_[i].entries[lists_[i].head];
}

void BucketQueue::respread(const float* factor) {
  // Collect in queue order (interval by interval, FIFO inside), then re-append in that order.
  std::vector<uint32_t> order;
  order.reserve(size_);
  double top = 0;
  for (const List& l : lists_)
    for (uint32_t j = l.head; j < l.entries.size(); ++j)
      if (l.entries[j] != kNone) {
        order.push_back(l.entries[j]);
        top = std::max(top, static_cast<double>(factor[l.entries[j]]));
      }
  for (uint32_t v : order)
    erase(v);
  map_.f_max = top;
  for (uint32_t v : order)
    link_back(v, map_.interval_of(factor[v]));
}

} // namespace vrs
