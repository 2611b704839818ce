#include "meshopt_streams.h"

#include <algorithm>
#include <cstring>

#ifdef VRS_HAVE_MESHOPTIMIZER
#include <meshoptimizer.h>
#endif

namespace vrs {

#ifdef VRS_HAVE_MESHOPTIMIZER

bool meshopt_available() {
  return true;
}

size_t meshopt_block_vertices(size_t stride) {
  // The vertex codec's block (vertexcodec.cpp, version 0): as many records as fit 8 KiB, a
  // multiple of 16, at most 256. A test pins it against the encoder's own output.
  const size_t fit = (8192 / stride) & ~size_t(15);
  return std::min<size_t>(fit, 256);
}

std::string compress_vertices(const uint8_t* records, size_t count, size_t stride,
                              const std::vector<size_t>& prefixes, CompressedVertices& out) {
  if (stride == 0 || stride % 4 != 0 || stride > 256) return "vertex records of unusual size";
  meshopt_encodeVertexVersion(0); // what EXT_meshopt_compression reads
  auto encode = [&](size_t n, std::vector<uint8_t>& into) {
    into.resize(meshopt_encodeVertexBufferBound(n, stride));
    into.resize(meshopt_encodeVertexBuffer(into.data(), into.size(), records, n, stride));
    return !into.empty();
  };
  if (!encode(count, out.stream)) return "the vertex encoder failed";
  const size_t tail = std::max<size_t>(stride, 32);
  out.tail.assign(out.stream.end() - tail, out.stream.end());
  out.prefix_bytes.clear();
  std::vector<uint8_t> part;
  for (size_t n : prefixes) {
    if (n == count) {
      out.prefix_bytes.push_back(out.stream.size() - tail);
      continue;
    }
    if (n % meshopt_block_vertices(stride) != 0 || n > count)
      return "a level's vertices do not end on a block of the vertex codec";
    if (!encode(n, part)) return "the vertex encoder failed";
    const size_t body = part.size() - tail;
    // The prefix's blocks must be the whole stream's first bytes: what lets a client decode
    // a coarser level from the first bytes it receives.
    if (body > out.stream.size() || std::memcmp(part.data(), out.stream.data(), body) != 0)
      return "the vertex codec's blocks of a prefix differ from the whole stream's";
    out.prefix_bytes.push_back(body);
  }
  return "";
}

std::string compress_indices(const std::vector<uint32_t>& indices, size_t vertex_count,
                             std::vector<uint8_t>& out) {
  if (indices.size() % 3 != 0) return "a triangle list holds a multiple of three indices";
  meshopt_encodeIndexVersion(1);
  out.resize(meshopt_encodeIndexBufferBound(indices.size(), vertex_count));
  out.resize(meshopt_encodeIndexBuffer(out.data(), out.size(), indices.data(), indices.size()));
  return out.empty() ? "the index encoder failed" : "";
}

void order_triangles_for_cache(std::vector<uint32_t>& indices, size_t vertex_count) {
  if (indices.empty()) return;
  meshopt_optimizeVertexCache(indices.data(), indices.data(), indices.size(), vertex_count);
}

#else // built without meshoptimizer's sources

bool meshopt_available() {
  return false;
}
size_t meshopt_block_vertices(size_t) {
  return 1;
}
std::string compress_vertices(const uint8_t*, size_t, size_t, const std::vector<size_t>&,
                              CompressedVertices&) {
  return "this build has no meshoptimizer encoder (scripts/setup.sh fetches its sources)";
}
std::string compress_indices(const std::vector<uint32_t>&, size_t, std::vector<uint8_t>&) {
  return "this build has no meshoptimizer encoder (scripts/setup.sh fetches its sources)";
}
void order_triangles_for_cache(std::vector<uint32_t>&, size_t) {}

#endif

} // namespace vrs
