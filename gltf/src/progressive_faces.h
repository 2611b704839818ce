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

  // The faces a decoder walks to from `first` steered by `bits` (one a side it meets), until
  // it has `patch.size()` of them: false, with `order` and `bits` undefined, when that walk
  // cannot find exactly the faces of `patch`.
  bool walk(uint32_t first, const std::vector<uint32_t>& patch, std::vector<uint32_t>& order,
            std::vector<uint8_t>& bits) const;

  // A side of a patch with no face of the patch across it: from corner a to corner b, and the
  // side across it (kNone on the mesh's border).
  struct OutlineSide {
    uint32_t a, b, across;
  };
  // The patch's outline in the order the decoders find it: the patch's faces in order, each
  // one's sides in order.
  void outline(const std::vector<uint32_t>& patch, std::vector<OutlineSide>& out) const;

  // Writes `faces` in order: the first into the slots of `patch` (in its order), the rest
  // appended; then pairs their sides by the record rule.
  void write(const std::vector<uint32_t>& patch, const std::vector<Face>& faces);

  // The side after `side` within its face (3 * slot + c: corner c + 1, wrapping to 0).
  static uint32_t next_corner(uint32_t side) { return side % 3 == 2 ? side - 2 : side + 1; }

 private:
  struct Outer {
    uint32_t a, b, side;
    bool used;
  };
  std::vector<uint32_t> corners_;    // 3 a slot
  std::vector<uint32_t> across_;     // per side (3 * slot + c, from corner c to c + 1)
  std::vector<OutlineSide> outline_; // write()'s scratch, kept between records
  std::vector<Outer> outer_;         // the same
  std::vector<uint32_t> sides_;
};

} // namespace vrs
