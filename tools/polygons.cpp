#include "polygons.h"

#include <algorithm>

namespace vrs_tool {

void Polygons::add_fan(uint32_t first_face, uint32_t corners) {
  const uint32_t p = uint32_t(count()), faces = corners - 2;
  if (of_.size() < first_face + faces) of_.resize(first_face + faces, kNone);
  corner_.push_back(3 * first_face);
  for (uint32_t t = 0; t < faces; ++t) {
    of_[first_face + t] = p;
    if (t == 0) corner_.push_back(3 * first_face + 1);
    corner_.push_back(3 * (first_face + t) + 2);
  }
  first_.push_back(uint32_t(corner_.size()));
}

std::vector<uint8_t> Polygons::face_flags(size_t face_count) const {
  if (empty()) return {};
  std::vector<uint8_t> flags(face_count, 0);
  for (size_t f = 0; f < std::min(face_count, of_.size()); ++f)
    flags[f] = of_[f] != kNone;
  return flags;
}

Polygons Polygons::surviving(const vrs::Report& report, const std::vector<uint32_t>& input,
                             const std::vector<uint32_t>& output) const {
  Polygons out;
  if (empty()) return out;
  std::vector<uint32_t> output_of(input.size() / 3, kNone); // input face -> output face
  for (size_t t = 0; t < report.face_source.size(); ++t)
    if (report.face_source[t] < output_of.size()) output_of[report.face_source[t]] = uint32_t(t);
  out.of_.assign(output.size() / 3, kNone);
  std::vector<uint32_t> corners;
  for (uint32_t p = 0; p < count(); ++p) {
    corners.clear();
    int turned = -1; // unknown; then 0 or 1 for every face of the polygon
    for (uint32_t k = 0; k < corner_count(p); ++k) {
      const uint32_t f = this->corners(p)[k] / 3, c = this->corners(p)[k] % 3;
      const uint32_t t = f < output_of.size() ? output_of[f] : kNone;
      if (t == kNone) break; // a triangle of it was replaced
      uint32_t at = 0;
      while (at < 3 && output[3 * t + at] != input[3 * f + c])
        ++at;
      if (at == 3) break;
      const int reversed = output[3 * t + (at + 1) % 3] != input[3 * f + (c + 1) % 3];
      if (turned >= 0 && reversed != turned) break;
      turned = reversed;
      corners.push_back(3 * t + at);
    }
    if (corners.size() != corner_count(p)) continue;
    if (turned == 1) std::reverse(corners.begin(), corners.end());
    const uint32_t q = uint32_t(out.count());
    for (uint32_t x : corners) {
      out.corner_.push_back(x);
      out.of_[x / 3] = q;
    }
    out.first_.push_back(uint32_t(out.corner_.size()));
  }
  return out;
}

} // namespace vrs_tool
