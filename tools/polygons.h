// Polygon faces (OBJ and OFF faces of more than three corners) through a run: read fanned into
// triangles, written back whole where the run left every triangle of theirs as it was, the
// rest plain triangles (as MeshLab's filter, pymeshlab and the numpy API keep them).
#pragma once

#include <cstdint>
#include <vector>

#include "vrs/simplify.h"

namespace vrs_tool {

class Polygons {
 public:
  static constexpr uint32_t kNone = 0xffffffffu;

  // A polygon of `corners` corners read as the fan of its first corner: the triangles
  // (c0, c1, c2), (c0, c2, c3), ... are the faces from `first_face` on.
  void add_fan(uint32_t first_face, uint32_t corners);
  bool empty() const { return first_.size() <= 1; }
  size_t count() const { return first_.size() - 1; }
  // Per face of `face_count`: whether it belongs to a polygon (Options::polygon_faces), or
  // empty when none does.
  std::vector<uint8_t> face_flags(size_t face_count) const;
  // The polygon a face belongs to, or kNone.
  uint32_t of(uint32_t face) const { return face < of_.size() ? of_[face] : kNone; }
  // A polygon's corners in order, each as face * 3 + corner.
  const uint32_t* corners(uint32_t p) const { return corner_.data() + first_[p]; }
  uint32_t corner_count(uint32_t p) const { return first_[p + 1] - first_[p]; }

  // The polygons of the output: those every triangle of which the run left untouched (the
  // report's face_source), in the same orientation or all reversed. `input` and `output` are
  // the triangles' vertices, the input's mapped through report.remap.
  Polygons surviving(const vrs::Report& report, const std::vector<uint32_t>& input_mapped,
                     const std::vector<uint32_t>& output) const;

 private:
  std::vector<uint32_t> first_{0}; // per polygon: its first entry in corner_
  std::vector<uint32_t> corner_;
  std::vector<uint32_t> of_; // per face: its polygon (kNone past the end)
};

} // namespace vrs_tool
