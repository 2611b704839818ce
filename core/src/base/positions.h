// A read-only view of the mesh's xyz floats, read as double vectors: what the input surface,
// the carried points and the error bound need of the mesh (the evaluator is one).
#pragma once

#include <cstdint>

#include "base/geometry.h"

namespace vrs {

class Positions {
 public:
  explicit Positions(const float* xyz) : pos_(xyz) {}
  Vec3 position(uint32_t v) const { return {pos_[3 * v], pos_[3 * v + 1], pos_[3 * v + 2]}; }
  void set_positions(const float* xyz) { pos_ = xyz; } // the array grew (fan_split.h)

 protected:
  const float* pos_;
};

} // namespace vrs
