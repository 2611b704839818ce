// The slide's own state (slide.cpp): which removed vertices a kept one may give its place to,
// and, for the fans it tries, each vertex they may ask about with its input faces and area.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vrs {

struct SlideState {
  // Per vertex: whether a kept vertex may slide onto it (setup.cpp); with per-corner data, one
  // of its input corners (else empty: 4 bytes a vertex at the peak).
  std::vector<uint8_t> target;
  std::vector<uint32_t> corner;
  // The vertices the fans tried may ask about, each a slot: a bit a vertex (it has a slot) and,
  // per 64 vertices, the slots before them.
  std::vector<uint64_t> bits;
  std::vector<uint32_t> rank;
  // Per slot, a third of its input faces' area, and its input faces: numbers into
  // InputSurface's faces, which stay in place since no slide builds the hierarchy that
  // reorders them (whole_input).
  std::vector<float> area;
  std::vector<uint32_t> first, faces;
  bool whole_input = false; // the input's hierarchy built by the run

  int slot(uint32_t v) const { // -1: none
    const uint64_t word = bits[v >> 6], bit = uint64_t(1) << (v & 63);
    return word & bit ? int(rank[v >> 6] + uint32_t(__builtin_popcountll(word & (bit - 1)))) : -1;
  }
  double area_of(uint32_t v) const {
    const int k = slot(v);
    return k >= 0 ? area[size_t(k)] : 0.0;
  }
};

} // namespace vrs
