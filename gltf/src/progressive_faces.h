// The faces a progressive mesh's decoder holds (docs/progressive.md, "the state a decoder
// keeps"), as the writer follows them: each face in its slot, and for each of its sides the
// side of another face across it. The decoders keep the same, by the same rules, so that a
// record can name its patch by one face and a few bits.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace vrs {

using Face = std::array<uint32_t, 3>;

class ProgressiveFaces {
 public:
  static constexpr uint32_t kNone = 0xffffffffu;

  // The base's faces (3 indices a face), their sides paired by the base rule.
  explicit ProgressiveFaces(const std::vector<uint32_t>& base);

  size_t size() const { return corners_.size() / 3; }
  uint32_t corner(uint32_t slot, int c) const { return corners_[3 * size_t(slot) + c]; }
  // The side across side c of `slot` (3 * slot + c: from corner c to c + 1), or kNone.
  uint32_t across(uint32_t slot, int c) const { return across_[3 * size_t(slot) + c]; }

  // The faces a decoder walks to from `first` steered by `bits` (one a side it meets), until
  // it has `patch.size()` of them: false, with `order` and `bits` undefined, when that walk
  // cannot find exactly the faces of `patch`.
  bool walk(uint32_t first, const std::vector<uint32_t>& patch, std::vector<uint32_t>& order,
            std::vector<uint8_t>& bits) const;

  // Writes `faces` in order: the first into the slots of `patch` (in its order), the rest
  // appended; then pairs their sides by the record rule.
  void write(const std::vector<uint32_t>& patch, const std::vector<Face>& faces);

 private:
  struct Outer {
    uint32_t a, b, side;
    bool used;
  };
  std::vector<uint32_t> corners_; // 3 a slot
  std::vector<uint32_t> across_;  // per side (3 * slot + c, from corner c to c + 1)
  std::vector<Outer> outer_;      // write()'s scratch, kept between records
  std::vector<uint32_t> sides_;
};

} // namespace vrs
