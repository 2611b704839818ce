// A set of undirected edges in one flat array (open addressing, linear probing): no node per
// edge and no allocation per insert, unlike std::unordered_set. Erased slots are tombstones,
// swept when the table is rebuilt.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vrs {

class FlatEdgeSet {
 public:
  // False when the edge was there already.
  bool insert(uint32_t a, uint32_t b);
  bool erase(uint32_t a, uint32_t b); // false when it was not there
  bool contains(uint32_t a, uint32_t b) const;
  size_t size() const { return size_; }

 private:
  static constexpr uint64_t kEmpty = ~uint64_t(0), kErased = kEmpty - 1; // never an edge key
  static constexpr size_t kNoSlot = ~size_t(0);
  static uint64_t key(uint32_t a, uint32_t b) {
    return a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a);
  }
  size_t slot_of(uint64_t k) const; // where k is, or the empty slot that ends its probe
  void rebuild(size_t capacity);

  std::vector<uint64_t> slots_; // a power of two in size
  size_t size_ = 0, used_ = 0;  // live keys; live keys and tombstones
};

} // namespace vrs
