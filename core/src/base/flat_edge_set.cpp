#include "base/flat_edge_set.h"

namespace vrs {

namespace {

uint64_t mix(uint64_t k) { // splitmix64's finaliser: neighbouring ids spread over the table
  k ^= k >> 30;
  k *= 0xbf58476d1ce4e5b9ull;
  k ^= k >> 27;
  k *= 0x94d049bb133111ebull;
  return k ^ (k >> 31);
}

} // namespace

size_t FlatEdgeSet::slot_of(uint64_t k) const {
  const size_t mask = slots_.size() - 1;
  size_t i = mix(k) & mask;
  while (slots_[i] != kEmpty && slots_[i] != k)
    i = (i + 1) & mask;
  return i;
}

void FlatEdgeSet::rebuild(size_t capacity) {
  std::vector<uint64_t> old;
  old.swap(slots_);
  slots_.assign(capacity, kEmpty);
  used_ = size_;
  for (uint64_t k : old)
    if (k != kEmpty && k != kErased) slots_[slot_of(k)] = k;
}

bool FlatEdgeSet::insert(uint32_t a, uint32_t b) {
  // At most half full, tombstones included, so that every probe ends soon.
  if (2 * (used_ + 1) > slots_.size()) {
    size_t capacity = 16; // room for twice the live keys: tombstones swept, then doubled
    while (capacity < 4 * (size_ + 1))
      capacity *= 2;
    rebuild(capacity);
  }
  const uint64_t k = key(a, b);
  // The first tombstone on the probe is where a new key goes.
  const size_t mask = slots_.size() - 1;
  size_t i = mix(k) & mask, free = kNoSlot;
  for (; slots_[i] != kEmpty; i = (i + 1) & mask) {
    if (slots_[i] == k) return false;
    if (slots_[i] == kErased && free == kNoSlot) free = i;
  }
  if (free == kNoSlot) {
    free = i;
    ++used_;
  }
  slots_[free] = k;
  ++size_;
  return true;
}

bool FlatEdgeSet::erase(uint32_t a, uint32_t b) {
  if (slots_.empty()) return false;
  const size_t i = slot_of(key(a, b));
  if (slots_[i] == kEmpty) return false;
  slots_[i] = kErased;
  --size_;
  return true;
}

bool FlatEdgeSet::contains(uint32_t a, uint32_t b) const {
  return !slots_.empty() && slots_[slot_of(key(a, b))] != kEmpty;
}

} // namespace vrs
