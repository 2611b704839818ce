#include "progressive_record.h"

#include <algorithm>
#include <array>

namespace vrs {

namespace {

constexpr uint32_t kNoSlot = 0xffffffffu;

// The faces of one record ordered around their common vertex `apex`, each rotated to start at
// it: false when they are no single fan.
bool as_fan(std::vector<Face>& faces, std::vector<uint32_t>& order, uint32_t apex, bool& closed) {
  const size_t k = faces.size();
  for (Face& f : faces) {
    const int at = f[0] == apex ? 0 : f[1] == apex ? 1 : f[2] == apex ? 2 : -1;
    if (at < 0) return false;
    std::rotate(f.begin(), f.begin() + at, f.end());
  }
  // The first face: one whose first ring vertex no other face ends at (an open fan's end).
  size_t start = 0;
  for (size_t i = 0; i < k; ++i) {
    bool follows = false;
    for (size_t j = 0; j < k && !follows; ++j)
      follows = j != i && faces[j][2] == faces[i][1];
    if (!follows) {
      start = i;
      break;
    }
  }
  order.assign(1, uint32_t(start));
  std::vector<uint8_t> used(k, 0);
  used[start] = 1;
  while (order.size() < k) {
    const uint32_t end = faces[order.back()][2];
    size_t next = k;
    for (size_t j = 0; j < k && next == k; ++j)
      if (!used[j] && faces[j][1] == end) next = j;
    if (next == k) return false;
    used[next] = 1;
    order.push_back(uint32_t(next));
  }
  closed = k >= 3 && faces[order.back()][2] == faces[order.front()][1];
  return true;
}

// A vertex of every face (a record's inserted vertex, unless a seam gave it copies), or kNoSlot.
uint32_t common_vertex(const std::vector<Face>& faces) {
  for (int c = 0; c < 3; ++c) {
    const uint32_t v = faces[0][c];
    bool everywhere = true;
    for (const Face& f : faces)
      everywhere = everywhere && (f[0] == v || f[1] == v || f[2] == v);
    if (everywhere) return v;
  }
  return kNoSlot;
}

} // namespace

RecordWriter::RecordWriter(const ProgressiveMesh& p, const std::vector<uint32_t>& triangles,
                           bool per_corner, VertexTable& table, const std::vector<uint32_t>& base)
    : p_(p), triangles_(triangles), per_corner_(per_corner), table_(table),
      fields_(table.normal_at(), table.color_at(), table.uv_at()), state_(base),
      slot_at_(triangles.size() / 3, kNoSlot) {
  // The decoder's slots: the base's faces first, then each face a record adds at the end.
  for (size_t i = 0; i < p.base_slots.size(); ++i)
    slot_at_[p.base_slots[i]] = uint32_t(i);
}

int64_t RecordWriter::newest_patch_face(uint32_t r) const {
  int64_t newest = -1;
  for (uint32_t j = p_.first[r]; j < p_.first[r + 1]; ++j)
    if (slot_at_[p_.slots[j]] != kNoSlot) newest = std::max(newest, int64_t(slot_at_[p_.slots[j]]));
  return newest;
}

bool RecordWriter::write(uint32_t r, std::vector<uint8_t>& stream) {
  const size_t before = table_.size(), record_start = stream.size();
  faces_.clear();
  input_slot_.clear();
  for (uint32_t j = p_.first[r]; j < p_.first[r + 1]; ++j) {
    Face f;
    for (int c = 0; c < 3; ++c)
      if (!table_.find_or_add(triangles_[p_.corners[3 * size_t(j) + c]],
                              per_corner_ ? p_.corners[3 * size_t(j) + c] : kNoRecord, f[c]))
        return false;
    faces_.push_back(f);
    input_slot_.push_back(p_.slots[j]);
  }
  const size_t k = faces_.size(), added = table_.size() - before;
  // The patch this record replaces: the faces now in its slots, in the order the walk from
  // the newest of them finds them (else listed).
  patch_slots_.clear();
  for (uint32_t s : input_slot_)
    if (slot_at_[s] != kNoSlot) patch_slots_.push_back(slot_at_[s]);
  const bool listed = patch_slots_.empty() ||
                      !state_.walk(*std::max_element(patch_slots_.begin(), patch_slots_.end()),
                                   patch_slots_, walked_, bits_);
  if (!listed) patch_slots_ = walked_;
  patch_.clear();
  for (uint32_t s : patch_slots_)
    for (int c = 0; c < 3; ++c)
      patch_.push_back(state_.corner(s, c));
  const uint32_t apex = common_vertex(faces_);
  size_t start = 0; // an open fan's first ring vertex, as a side of the outline
  const Shape shape = apex == kNoSlot ? kCorners : fan_shape(apex, start);
  // A vertex reference: one the record adds, a corner of the patch, or an older vertex.
  auto ref = [&](uint32_t v) -> uint64_t {
    if (v >= before) return v - before;
    for (size_t i = 0; i < patch_.size(); ++i)
      if (patch_[i] == v) return added + i;
    return added + patch_.size() + (before - 1 - v);
  };
  const bool regular = shape != kCorners && added == 1 && apex == before;
  put_varint(stream, uint64_t(k) << 4 | uint64_t(listed) << 3 | shape << 1 | !regular);
  if (!regular) {
    put_varint(stream, added);
    if (shape != kCorners) put_varint(stream, ref(apex));
  }
  const size_t live_faces = state_.size();
  if (shape == kCorners || shape == kListedRing) put_varint(stream, patch_slots_.size());
  if (listed) {
    for (uint32_t s : patch_slots_) // how far back from the last face
      put_varint(stream, uint64_t(live_faces) - 1 - s);
  } else {
    put_varint(stream, zigzag(int64_t(patch_slots_[0]) - previous_first_));
    previous_first_ = patch_slots_[0];
  }
  if (shape == kOpenFan) {
    put_varint(stream, start);
  } else if (shape == kListedRing) {
    put_varint(stream, ring_.size() - k); // 0: closed, 1: open
    for (uint32_t v : ring_)
      put_varint(stream, ref(v));
  } else if (shape == kCorners) {
    for (const Face& f : faces_)
      for (uint32_t v : f)
        put_varint(stream, ref(v));
  }
  // Then one run of bits to the record's end: the walk's steering bits, the new vertices.
  topology_bits_ += 8 * (stream.size() - record_start) + (listed ? 0 : bits_.size());
  {
    BitWriter bits(stream);
    if (!listed)
      for (uint8_t b : bits_)
        bits.put(b, 1);
    put_vertices(bits, before);
  }
  // As the decoder does: the faces in order into the patch's slots, the rest at the end.
  for (size_t i = 0; i < k; ++i)
    slot_at_[input_slot_[i]] =
        i < patch_slots_.size() ? patch_slots_[i] : uint32_t(live_faces + i - patch_slots_.size());
  state_.write(patch_slots_, faces_);
  return true;
}

// The record's faces as a fan around `apex`, in the ring's order (faces_ and input_slot_ put in
// it, ring_ filled): kClosedFan or kOpenFan when the ring is the patch's outline, as a decoder
// finds it (`start`: the open fan's first side of it), else kListedRing; kCorners when the
// faces are no single fan.
RecordWriter::Shape RecordWriter::fan_shape(uint32_t apex, size_t& start) {
  const size_t k = faces_.size();
  bool closed = false;
  turned_ = faces_;
  if (!as_fan(turned_, order_, apex, closed)) return kCorners;
  const size_t sides = closed ? k : k + 1;
  state_.outline(patch_slots_, outline_);
  if (closed && !outline_.empty()) // a closed fan starts where the outline does
    for (size_t i = 0; i < k; ++i)
      if (turned_[order_[i]][1] == outline_[0].a) {
        std::rotate(order_.begin(), order_.begin() + i, order_.end());
        break;
      }
  ring_.clear();
  for (uint32_t i : order_)
    ring_.push_back(turned_[i][1]);
  if (!closed) ring_.push_back(turned_[order_.back()][2]);
  faces_.clear();
  slots_in_order_.clear();
  for (uint32_t i : order_)
    faces_.push_back(turned_[i]), slots_in_order_.push_back(input_slot_[i]);
  input_slot_.swap(slots_in_order_);
  // The ring as the outline gives it: each side once, the patch's way round.
  bool fan = outline_.size() == sides && patch_.size() == 3 * (sides - 2) &&
             (!closed || ring_[0] == outline_[0].a);
  for (size_t i = 0; i < sides && fan; ++i) {
    const uint32_t from = ring_[i], to = ring_[(i + 1) % sides];
    size_t at = 0;
    while (at < outline_.size() && outline_[at].a != from)
      ++at;
    fan = at < outline_.size() && outline_[at].b == to;
    if (i == 0) start = at;
  }
  return !fan ? kListedRing : closed ? kClosedFan : kOpenFan;
}

// Each new vertex against the mean of the older vertices its faces touch.
void RecordWriter::put_vertices(BitWriter& bits, size_t before) {
  for (uint32_t v = uint32_t(before); v < table_.size(); ++v) {
    known_.clear();
    for (const Face& f : faces_)
      if (f[0] == v || f[1] == v || f[2] == v)
        for (uint32_t u : f)
          if (u < before &&
              std::find(known_.begin(), known_.end(), vertex_bytes(u)) == known_.end())
            known_.push_back(vertex_bytes(u));
    put_residuals(bits, fields_, vertex_bytes(v), known_,
                  v > before ? vertex_bytes(v - 1) : nullptr);
  }
}

} // namespace vrs
