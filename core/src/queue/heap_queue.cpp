#include "queue/heap_queue.h"

namespace vrs {

void HeapQueue::init(size_t vertex_count, const IntervalMap& map, Workers*) {
  map_ = map;
  heap_.clear();
  heap_.reserve(vertex_count);
  pos_.assign(vertex_count, kNone);
  seq_ = 0;
}

void HeapQueue::place(size_t i, const Entry& e) {
  heap_[i] = e;
  pos_[e.v] = static_cast<uint32_t>(i);
}

void HeapQueue::sift_up(size_t i) {
  Entry e = heap_[i];
  while (i > 0) {
    size_t parent = (i - 1) / 2;
    if (!less(e, heap_[parent])) break;
    place(i, heap_[parent]);
    i = parent;
  }
  place(i, e);
}

void HeapQueue::sift_down(size_t i) {
  Entry e = heap_[i];
  const size_t n = heap_.size();
  for (;;) {
    size_t c = 2 * i + 1;
    if (c >= n) break;
    if (c + 1 < n && less(heap_[c + 1], heap_[c])) ++c;
    if (!less(heap_[c], e)) break;
    place(i, heap_[c]);
    i = c;
  }
  place(i, e);
}

void HeapQueue::push(uint32_t v, double factor) {
  if (contains(v)) erase(v);
  heap_.push_back(Entry{factor, seq_++, v});
  sift_up(heap_.size() - 1);
}

void HeapQueue::erase(uint32_t v) {
  uint32_t i = pos_[v];
  if (i == kNone) return;
  pos_[v] = kNone;
  Entry last = heap_.back();
  heap_.pop_back();
  if (i == heap_.size()) return;
  place(i, last);
  sift_up(i);
  sift_down(pos_[last.v]);
}

} // namespace vrs
