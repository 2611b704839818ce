// What an OBJ's vt and vn lines hold, so that tiles tell a seam by the corners' values as the
// in-core run does, not by which line a corner names (a file may write one value on several
// lines: every corner its own vn line, as unindexed exporters do). The streaming pass writes
// them to the work directory (texcoords.bin: u v; normals.bin: x y z; floats), and each tile
// maps them and reads only its own corners' lines.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace vrs::tiled {

class CornerValues {
 public:
  // Maps `path`, `floats` values a line; a missing or empty file maps nothing.
  CornerValues(const std::string& path, int floats);
  ~CornerValues();
  CornerValues(const CornerValues&) = delete;
  CornerValues& operator=(const CornerValues&) = delete;
  bool empty() const { return lines_ == 0; }
  // Line `key`'s values (keys count from 1; 0 names none): null when none or past the end.
  const float* at(uint32_t key) const {
    return key && key <= lines_ ? data_ + size_t(key - 1) * size_t(floats_) : nullptr;
  }

 private:
  const float* data_ = nullptr;
  size_t bytes_ = 0, lines_ = 0;
  int floats_;
};

// The in-core run's tests, on keys: two texture coordinates are one when their values have the
// same bits; two normals when theirs do, or when both are nonzero and turn no more than the
// crease angle apart (cos `crease_cos`; the CLI's 60 degrees) — smooth shading. Without
// values (null or an empty map: a PLY's keys are the values' bits), equal keys.
bool same_texcoord(const CornerValues* vt, uint32_t a, uint32_t b);
bool same_normal(const CornerValues* vn, uint32_t a, uint32_t b, double crease_cos);

// Whether every face of keys.bin (`faces` records) names one normal value at its three corners
// (flat shading, as the in-core run tells it: by the values' bits, a missing normal as zero).
bool flat_by_value(const std::string& keys_path, uint64_t faces, const CornerValues& vn);

} // namespace vrs::tiled
