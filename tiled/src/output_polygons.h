// The input's polygons the output holds whole (an OBJ's or OFF's faces of more than three
// corners, polygons.bin over faces.bin): those every triangle of which is an untouched
// triangle of the output (FaceRecord::polygon), corners in the input's order, so that the
// output writes them back as the in-core run does. Memory: the output's untouched polygon
// triangles, not the whole output.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "partition.h"

namespace vrs::tiled {

class OutputPolygons {
 public:
  static constexpr uint32_t kNone = 0xffffffffu;
  // Reads the work directory's polygons (none: empty) and the output's marked triangles.
  OutputPolygons(const std::string& dir, const FaceSource& faces);
  bool empty() const { return first_.size() <= 1; }
  uint32_t count() const { return uint32_t(first_.size() - 1); }
  // The whole polygon an output triangle belongs to, or kNone.
  uint32_t of(const FaceRecord& r) const;
  uint32_t corner_count(uint32_t p) const { return first_[p + 1] - first_[p]; }
  // Corner k of polygon p: its vertex and its per-corner keys (as FaceRecord::a, b).
  uint32_t vertex(uint32_t p, uint32_t k) const { return v_[first_[p] + k]; }
  uint32_t key_a(uint32_t p, uint32_t k) const { return a_[first_[p] + k]; }
  uint32_t key_b(uint32_t p, uint32_t k) const { return b_[first_[p] + k]; }
  // Triangles fewer than the output's count once each polygon is one face.
  uint64_t merged() const { return merged_; }

 private:
  struct Key {
    uint32_t v[3];
    bool operator==(const Key& o) const {
      return v[0] == o.v[0] && v[1] == o.v[1] && v[2] == o.v[2];
    }
  };
  struct Hash {
    size_t operator()(const Key& k) const {
      return (size_t(k.v[0]) * 0x9e3779b97f4a7c15ull) ^ (size_t(k.v[1]) * 0xc2b2ae3d27d4eb4full) ^
             size_t(k.v[2]);
    }
  };
  struct Corners {
    uint32_t a[3], b[3];
    uint32_t polygon = kNone;
  };
  std::unordered_map<Key, Corners, Hash> marked_; // the output's untouched polygon triangles
  std::vector<uint32_t> first_{0}, v_, a_, b_;
  uint64_t merged_ = 0;
};

} // namespace vrs::tiled
