// One insertion record at a time, coded as docs/progressive.md's "a record" says: its patch,
// named by a walk or listed, its shape, its new vertices as residuals. The writer follows the
// decoder's state (its faces, their sides across, its vertices) and advances it as a decoder
// will, record by record.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "progressive_coding.h"
#include "progressive_faces.h"
#include "vertex_table.h"
#include "vrs/progressive.h"

namespace vrs {

class RecordWriter {
 public:
  // `triangles`: the input's, which the corners of `p` name; `per_corner`: the corners carry
  // their own attributes; `base`: the base's faces as glTF vertices of `table`, which the
  // records add to.
  RecordWriter(const ProgressiveMesh& p, const std::vector<uint32_t>& triangles, bool per_corner,
               VertexTable& table, const std::vector<uint32_t>& base);

  // The newest face of the decoder's that record r replaces, or -1.
  int64_t newest_patch_face(uint32_t r) const;
  // Appends record r to `stream`; false when one of its vertices has a non-finite coordinate.
  bool write(uint32_t r, std::vector<uint8_t>& stream);

  size_t faces() const { return state_.size(); }
  size_t topology_bytes() const { return (topology_bits_ + 7) / 8; } // all but the vertices

 private:
  // A record's shapes: its faces (apex, ring[i], ring[i + 1]) around a fan whose ring is the
  // patch's outline (closed, or open: all of it but one side), or around a ring it lists, or
  // each face's three corners as they are (a fan broken by a seam's copies).
  enum Shape : uint32_t { kCorners = 0, kClosedFan = 1, kOpenFan = 2, kListedRing = 3 };

  Shape fan_shape(uint32_t apex, size_t& start);
  void put_vertices(BitWriter& bits, size_t before);
  const uint8_t* vertex_bytes(uint32_t v) const {
    return table_.bytes().data() + size_t(v) * table_.stride();
  }

  const ProgressiveMesh& p_;
  const std::vector<uint32_t>& triangles_;
  const bool per_corner_;
  VertexTable& table_;
  const VertexFields fields_;
  ProgressiveFaces state_;
  std::vector<uint32_t> slot_at_; // input slot -> decoder slot (kNone: empty)
  int64_t previous_first_ = 0;    // the last walked patch's first face
  size_t topology_bits_ = 0;
  // Scratch, kept between records.
  std::vector<Face> faces_, turned_;
  std::vector<uint32_t> order_, input_slot_, slots_in_order_, patch_slots_, walked_, patch_, ring_;
  std::vector<uint8_t> bits_;
  std::vector<ProgressiveFaces::OutlineSide> outline_;
  std::vector<const uint8_t*> known_;
};

} // namespace vrs
