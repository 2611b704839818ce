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

#include "glb_file.h"
#include "glb_json.h"
#include "meshopt_streams.h"
#include "vertex_table.h"

namespace vrs {

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

  // The binary chunk: the coarsest level's indices, the vertices, the finer levels' indices.
  std::vector<const std::vector<uint8_t>*> pieces = {&ib[n - 1], &vb};
  for (size_t k = n - 1; k-- > 0;)
    pieces.push_back(&ib[k]);
  size_t json_bytes = 0;
  const std::string written = write_glb_file(path, json, pieces, &json_bytes);
  if (!written.empty()) return written;
  const size_t total = 12 + 8 + json_bytes + 8 + bin_bytes;

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
