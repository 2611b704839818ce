// glTF vertices: input vertices split where their corners' data differ, as interleaved
// records (position, then each attribute the input has), in an order the writer chooses.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "vrs/glb.h"

namespace vrs {

constexpr uint32_t kNoRecord = 0xffffffffu;

class VertexTable {
 public:
  VertexTable(const float* positions, size_t input_vertices, const GlbAttributes& a)
      : pos_(positions), a_(a), first_(input_vertices, kNoRecord) {
    stride_ = 12;
    if (a.normals || a.corner_normals) normal_at_ = stride_, stride_ += 12;
    if (a.colors || a.corner_colors) color_at_ = stride_, stride_ += 4;
    if (a.uvs || a.corner_uvs) uv_at_ = stride_, stride_ += 8;
    record_.resize(stride_);
  }
  size_t stride() const { return stride_; }
  int normal_at() const { return normal_at_; }
  int color_at() const { return color_at_; }
  int uv_at() const { return uv_at_; }
  size_t size() const { return next_.size(); }
  const std::vector<uint8_t>& bytes() const { return bytes_; }
  const float* low() const { return low_; }
  const float* high() const { return high_; }

  // The record of input vertex v seen through input corner `corner` (kNoRecord: none); false
  // when its position is not finite (glTF has no place for it).
  bool find_or_add(uint32_t v, uint32_t corner, uint32_t& out) {
    float p[3] = {pos_[3 * size_t(v)], pos_[3 * size_t(v) + 1], pos_[3 * size_t(v) + 2]};
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return false;
    std::memcpy(record_.data(), p, 12);
    if (normal_at_ >= 0) {
      const float* n = a_.corner_normals && corner != kNoRecord
                           ? a_.corner_normals + 3 * size_t(corner)
                       : a_.normals ? a_.normals + 3 * size_t(v)
                                    : nullptr;
      float u[3] = {0, 0, 1}; // a zero or missing normal: glTF asks for unit length
      if (n) {
        const double l = std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
        if (l > 0 && std::isfinite(l))
          for (int c = 0; c < 3; ++c)
            u[c] = float(n[c] / l);
      }
      std::memcpy(record_.data() + normal_at_, u, 12);
    }
    if (color_at_ >= 0) {
      const float* c = a_.corner_colors && corner != kNoRecord
                           ? a_.corner_colors + 4 * size_t(corner)
                       : a_.colors ? a_.colors + 4 * size_t(v)
                                   : nullptr;
      for (int k = 0; k < 4; ++k) {
        const float x = c && std::isfinite(c[k]) ? std::min(1.0f, std::max(0.0f, c[k])) : 1.0f;
        record_[color_at_ + k] = uint8_t(std::lround(x * 255.0f));
      }
    }
    if (uv_at_ >= 0) {
      const float* t = a_.corner_uvs && corner != kNoRecord ? a_.corner_uvs + 2 * size_t(corner)
                       : a_.uvs                             ? a_.uvs + 2 * size_t(v)
                                                            : nullptr;
      // glTF puts (0, 0) at the image's top left; OBJ and PLY at its bottom left.
      float uv[2] = {t ? t[0] : 0.0f, t ? 1.0f - t[1] : 0.0f};
      for (float& x : uv)
        if (!std::isfinite(x)) x = 0;
      std::memcpy(record_.data() + uv_at_, uv, 8);
    }
    for (uint32_t r = first_[v]; r != kNoRecord; r = next_[r])
      if (std::memcmp(bytes_.data() + size_t(r) * stride_, record_.data(), stride_) == 0) {
        out = r;
        return true;
      }
    out = uint32_t(next_.size());
    next_.push_back(first_[v]);
    vertex_of_.push_back(v);
    first_[v] = out;
    bytes_.insert(bytes_.end(), record_.begin(), record_.end());
    for (int c = 0; c < 3; ++c) {
      low_[c] = std::min(low_[c], p[c]);
      high_[c] = std::max(high_[c], p[c]);
    }
    return true;
  }

  // The records added since `from`, put in the order of their vertices' `rank` (the chain's
  // shared order): without split vertices the glTF vertices are then exactly that order.
  // `indices` (the level just added) follow.
  void order_since(size_t from, const std::vector<uint32_t>& rank, std::vector<uint32_t>& indices) {
    reorder_since(from, indices, [&](uint32_t a, uint32_t b) {
      return rank[vertex_of_[a]] < rank[vertex_of_[b]];
    });
  }
  // The same, in the order the level's indices first use them (what the codecs compress best).
  void order_since_by_use(size_t from, std::vector<uint32_t>& indices) {
    std::vector<uint32_t> first(next_.size() - from, kNoRecord);
    for (size_t i = 0; i < indices.size(); ++i)
      if (indices[i] >= from && first[indices[i] - from] == kNoRecord)
        first[indices[i] - from] = uint32_t(i);
    reorder_since(from, indices,
                  [&](uint32_t a, uint32_t b) { return first[a - from] < first[b - from]; });
  }
  // Copies of the last record until the count is a multiple of `block` (unreferenced: a
  // stream's padding). Not found by find_or_add.
  void pad_to(size_t block) {
    while (next_.size() % block != 0) {
      const size_t last = next_.size() - 1;
      bytes_.insert(bytes_.end(), bytes_.begin() + last * stride_,
                    bytes_.begin() + (last + 1) * stride_);
      next_.push_back(kNoRecord);
      vertex_of_.push_back(vertex_of_[last]);
    }
  }

 private:
  template <class Less> void reorder_since(size_t from, std::vector<uint32_t>& indices, Less less) {
    const size_t count = next_.size() - from;
    std::vector<uint32_t> by_rank(count);
    for (size_t i = 0; i < count; ++i)
      by_rank[i] = uint32_t(from + i);
    std::stable_sort(by_rank.begin(), by_rank.end(), less);
    std::vector<uint32_t> new_id(count);
    for (size_t i = 0; i < count; ++i)
      new_id[by_rank[i] - from] = uint32_t(from + i);
    auto moved = [&](uint32_t r) { return r != kNoRecord && r >= from ? new_id[r - from] : r; };
    std::vector<uint8_t> bytes(count * stride_);
    std::vector<uint32_t> next(count), vertex(count);
    for (size_t i = 0; i < count; ++i) {
      const uint32_t old = by_rank[i];
      std::memcpy(bytes.data() + i * stride_, bytes_.data() + size_t(old) * stride_, stride_);
      next[i] = moved(next_[old]);
      vertex[i] = vertex_of_[old];
    }
    for (size_t r = from; r < next_.size(); ++r) // each vertex's newest record, once
      if (first_[vertex_of_[r]] == r) first_[vertex_of_[r]] = new_id[r - from];
    std::memcpy(bytes_.data() + from * stride_, bytes.data(), bytes.size());
    std::copy(next.begin(), next.end(), next_.begin() + from);
    std::copy(vertex.begin(), vertex.end(), vertex_of_.begin() + from);
    for (uint32_t& i : indices)
      i = moved(i);
  }

  const float* pos_;
  const GlbAttributes& a_;
  size_t stride_;
  int normal_at_ = -1, color_at_ = -1, uv_at_ = -1;
  std::vector<uint8_t> record_, bytes_;
  std::vector<uint32_t> first_, next_; // per input vertex its records, chained
  std::vector<uint32_t> vertex_of_;    // per record its input vertex
  float low_[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                   std::numeric_limits<float>::infinity()};
  float high_[3] = {-low_[0], -low_[1], -low_[2]};
};

} // namespace vrs
