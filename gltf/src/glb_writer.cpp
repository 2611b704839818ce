// The .glb of a chain of levels (glb.h): glTF vertices (input vertices split where their
// corners' data differ), then the JSON and the binary chunk in the streaming order.
#include "vrs/glb.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <unistd.h>

#include "glb_json.h"
#include "meshopt_streams.h"

namespace vrs {

namespace {

constexpr uint32_t kNoRecord = 0xffffffffu;

// glTF vertices as interleaved records: position, then each attribute the input has.
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

size_t pad4(size_t n) {
  return (n + 3) & ~size_t(3);
}

void put_u32(std::vector<uint8_t>& out, uint32_t x) {
  for (int i = 0; i < 4; ++i)
    out.push_back(uint8_t(x >> (8 * i)));
}

// One level's indices, as bytes: 16 bits when its vertices allow (65535 is the primitive
// restart value glTF forbids as an index), else 32.
std::vector<uint8_t> index_bytes(const std::vector<uint32_t>& idx, size_t vertices, bool& wide) {
  wide = vertices >= 65535;
  std::vector<uint8_t> out(idx.size() * (wide ? 4 : 2));
  for (size_t i = 0; i < idx.size(); ++i)
    if (wide)
      std::memcpy(out.data() + 4 * i, &idx[i], 4);
    else {
      const uint16_t s = uint16_t(idx[i]);
      std::memcpy(out.data() + 2 * i, &s, 2);
    }
  out.resize(pad4(out.size()), 0);
  return out;
}

} // namespace

std::string write_glb(const std::string& path, const float* positions, size_t vertex_count,
                      const LodChain& chain, const GlbAttributes& a, GlbLayout* layout) {
  if (!chain.ok || chain.levels.empty()) return "no levels to write";
  const bool corners = a.corner_normals || a.corner_colors || a.corner_uvs;
  for (const LodLevel& l : chain.levels)
    if (corners && l.corner_source.size() != l.triangles.size())
      return "per-corner data needs the levels' corner sources";
  for (uint32_t v : chain.vertices)
    if (v >= vertex_count) return "a level names a vertex the mesh does not have";

  // glTF vertices, coarsest level first; each level's indices into them.
  VertexTable table(positions, vertex_count, a);
  const size_t n = chain.levels.size();
  std::vector<std::vector<uint32_t>> indices(n);
  std::vector<size_t> prefix(n);
  std::vector<std::array<float, 6>> bounds(n);
  std::vector<uint32_t> rank(vertex_count, kNoRecord);
  for (size_t i = 0; i < chain.vertices.size(); ++i)
    rank[chain.vertices[i]] = uint32_t(i);
  if (a.compress && !meshopt_available())
    return "this build cannot compress: it has no meshoptimizer encoder (scripts/setup.sh "
           "fetches its sources)";
  const size_t block = a.compress ? meshopt_block_vertices(table.stride()) : 1;
  for (size_t k = n; k-- > 0;) {
    const LodLevel& l = chain.levels[k];
    const size_t before = table.size();
    indices[k].resize(l.triangles.size());
    for (size_t c = 0; c < l.triangles.size(); ++c)
      if (!table.find_or_add(chain.vertices[l.triangles[c]],
                             corners ? l.corner_source[c] : kNoRecord, indices[k][c]))
        return "a face has a vertex with a non-finite coordinate, which glTF cannot hold";
    if (a.compress) {
      // The level's triangles in the vertex cache's order and its new vertices as they are
      // first used: the order both codecs compress best (the shared order only asks that a
      // level's vertices follow the coarser ones'). A prefix ends on a codec block.
      order_triangles_for_cache(indices[k], table.size());
      table.order_since_by_use(before, indices[k]);
      if (k > 0) table.pad_to(block);
    } else {
      table.order_since(before, rank, indices[k]);
    }
    prefix[k] = table.size();
    for (int c = 0; c < 3; ++c)
      bounds[k][c] = table.low()[c], bounds[k][3 + c] = table.high()[c];
  }
  for (size_t k = 0; k < n; ++k)
    if (prefix[k] == 0) return "a level has no faces: glTF needs at least one";

  // The binary chunk: coarsest indices, the vertices, then the finer levels' indices.
  std::vector<std::vector<uint8_t>> ib(n);
  std::vector<bool> wide(n);
  for (size_t k = 0; k < n; ++k) {
    bool w = false;
    ib[k] = index_bytes(indices[k], prefix[k], w);
    wide[k] = w;
  }
  CompressedVertices cv;
  std::vector<uint8_t> vb = table.bytes();   // what the chunk holds of the vertices
  std::vector<size_t> packed_index_bytes(n); // a compressed stream's own length, unpadded
  if (a.compress) {
    std::vector<size_t> prefixes(prefix.begin(), prefix.end());
    std::string err = compress_vertices(vb.data(), table.size(), table.stride(), prefixes, cv);
    for (size_t k = 0; k < n && err.empty(); ++k) {
      err = compress_indices(indices[k], prefix[k], ib[k]);
      packed_index_bytes[k] = ib[k].size();
      ib[k].resize(pad4(ib[k].size()), 0);
    }
    if (!err.empty()) return err;
    vb = cv.stream;
  }
  std::vector<size_t> index_at(n);
  size_t at = 0;
  index_at[n - 1] = at;
  at += ib[n - 1].size();
  const size_t vertex_at = at;
  at += pad4(vb.size());
  for (size_t k = n - 1; k-- > 0;) {
    index_at[k] = at;
    at += ib[k].size();
  }
  const size_t bin_bytes = at;

  GlbJson j(a, table.stride(), table.normal_at(), table.color_at(), table.uv_at());
  j.buffer(bin_bytes);
  int vertex_view;
  std::vector<int> index_view(n);
  if (a.compress) {
    // Decoded, the views lie one after the other in the fallback buffer (which has no bytes).
    size_t decoded = 0;
    vertex_view = j.compressed_view(decoded, table.bytes().size(), table.stride(), 34962, vertex_at,
                                    cv.stream.size(), "ATTRIBUTES", table.size(), cv.tail);
    decoded += pad4(table.bytes().size());
    for (size_t k = 0; k < n; ++k) {
      const size_t size = wide[k] ? 4 : 2, bytes = indices[k].size() * size;
      index_view[k] = j.compressed_view(decoded, bytes, size, 34963, index_at[k],
                                        packed_index_bytes[k], "TRIANGLES", indices[k].size(), {});
      decoded += pad4(bytes);
    }
    j.fallback(decoded);
  } else {
    vertex_view = j.view(vertex_at, table.bytes().size(), table.stride(), 34962);
    for (size_t k = 0; k < n; ++k)
      index_view[k] = j.view(index_at[k], indices[k].size() * (wide[k] ? 4 : 2), 0, 34963);
  }
  for (size_t k = 0; k < n; ++k) {
    const LodLevel& l = chain.levels[k];
    j.level(vertex_view, prefix[k], bounds[k].data(), index_view[k], indices[k].size(), wide[k],
            l.ratio, k < a.level_errors.size() ? a.level_errors[k] : -1.0,
            a.compress ? cv.prefix_bytes[k] : 0);
  }
  const std::string json = j.finish();

  // The file: header, JSON chunk (padded with spaces), binary chunk (padded with zeros).
  std::vector<uint8_t> head;
  const size_t json_bytes = pad4(json.size());
  const size_t total = 12 + 8 + json_bytes + 8 + bin_bytes;
  if (total > 0xffffffffu) return "the levels need more than the 4 GiB a .glb can hold";
  put_u32(head, 0x46546C67); // "glTF"
  put_u32(head, 2);
  put_u32(head, uint32_t(total));
  put_u32(head, uint32_t(json_bytes));
  put_u32(head, 0x4E4F534A); // "JSON"
  head.insert(head.end(), json.begin(), json.end());
  head.resize(12 + 8 + json_bytes, ' ');
  put_u32(head, uint32_t(bin_bytes));
  put_u32(head, 0x004E4942); // "BIN\0"

  const size_t slash = path.rfind('/');
  const std::string tmp = path.substr(0, slash + 1) + ".vrsimplify-" + std::to_string(getpid()) +
                          "-" + path.substr(slash + 1);
  FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) return "cannot write " + path + ": " + std::strerror(errno);
  static const uint8_t zeros[4] = {0, 0, 0, 0};
  bool ok = std::fwrite(head.data(), 1, head.size(), f) == head.size();
  ok = ok && std::fwrite(ib[n - 1].data(), 1, ib[n - 1].size(), f) == ib[n - 1].size();
  ok = ok && std::fwrite(vb.data(), 1, vb.size(), f) == vb.size();
  const size_t pad = pad4(vb.size()) - vb.size();
  ok = ok && std::fwrite(zeros, 1, pad, f) == pad;
  for (size_t k = n - 1; k-- > 0;)
    ok = ok && std::fwrite(ib[k].data(), 1, ib[k].size(), f) == ib[k].size();
  ok = std::fclose(f) == 0 && ok;
  if (!ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    return "cannot write " + path + ": " + why;
  }

  if (layout) {
    const size_t bin_start = 12 + 8 + json_bytes + 8;
    layout->file_bytes = total;
    layout->compressed = a.compress;
    layout->vertex_count = table.size();
    layout->vertex_stride = table.stride();
    layout->vertex_offset = bin_start + vertex_at;
    layout->levels.assign(n, {});
    for (size_t k = 0; k < n; ++k) {
      GlbLayout::Level& L = layout->levels[k];
      L.vertex_count = prefix[k];
      L.faces = indices[k].size() / 3;
      L.index_offset = bin_start + index_at[k];
      L.index_bytes = ib[k].size();
      L.vertex_bytes = a.compress ? cv.prefix_bytes[k] : prefix[k] * table.stride();
      // The header and JSON, its vertex prefix and its indices (for the coarsest level, one
      // prefix of the file; compressed, the stream's tail is in the JSON).
      L.bytes_to_draw = bin_start + L.vertex_bytes + L.index_bytes;
    }
  }
  return "";
}

} // namespace vrs
