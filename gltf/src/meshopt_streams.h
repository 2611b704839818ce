// EXT_meshopt_compression's streams for the levels-of-detail .glb, through meshoptimizer's
// own encoder (vertex codec version 0, index codec version 1, as the extension reads them):
// lossless, so positions stay the input's floats bit for bit.
//
// Streaming survives compression. The vertex codec works in blocks of a fixed count of
// vertices, each block encoded against the last vertex of the block before, and ends the
// stream with a tail holding the first vertex. So when every level's vertex prefix ends on a
// block boundary (pad_to_blocks), the first bytes of the one compressed vertex stream, with
// the tail after them, are themselves a valid stream of that prefix: a client that has
// received them decodes the coarser level without the rest (web/lod_stream.js). Standard
// readers (three.js, Babylon.js) decode the whole stream as usual.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace vrs {

// Whether this build holds meshoptimizer's encoder (its sources are a build input, fetched by
// scripts/setup.sh; a build without them writes uncompressed files only).
bool meshopt_available();

// The number of vertices in one block of the vertex codec for records of `stride` bytes:
// a level's prefix must be a multiple of it (its last level excepted) to decode alone.
size_t meshopt_block_vertices(size_t stride);

struct CompressedVertices {
  std::vector<uint8_t> stream;      // the whole stream: header, blocks, tail
  std::vector<size_t> prefix_bytes; // per prefix asked: its header and blocks, without tail
  std::vector<uint8_t> tail;        // the stream's tail (what every prefix's decoding needs)
};

// Encodes `count` records of `stride` bytes; for each of `prefixes` (record counts, each a
// multiple of meshopt_block_vertices or the whole count) also the length of the stream's
// bytes that hold it. Empty string on success.
std::string compress_vertices(const uint8_t* records, size_t count, size_t stride,
                              const std::vector<size_t>& prefixes, CompressedVertices& out);

// Encodes a triangle list (16- or 32-bit indices by `wide`). Empty string on success.
std::string compress_indices(const std::vector<uint32_t>& indices, size_t vertex_count,
                             std::vector<uint8_t>& out);

// Reorders the triangles of `indices` (a list of triangles) for the GPU's vertex cache, which
// is also the order the index codec compresses best. Triangles keep their corners' order.
void order_triangles_for_cache(std::vector<uint32_t>& indices, size_t vertex_count);

} // namespace vrs
