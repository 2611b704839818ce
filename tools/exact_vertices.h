// The input's vertices as the file holds them, so that the in-core run keeps them untouched
// where vcglib's mesh (float) cannot: coordinates that a float cannot hold (a georeferenced
// terrain at x ~ 500 000, y ~ 4 100 000 m, where a float steps by 0.25-0.5 m; double PLY
// properties; text with more digits), and text outputs (vcglib prints OFF with 7 digits). The
// core then takes its positions from the doubles, from the first vertex on (float holds the
// mesh's own detail); the output's vertices are rewritten from the input's: a PLY's records,
// every property in its own type, bit for bit in binary and with round-trip digits in ascii (9
// significant for float, 17 for double); an OBJ's `v` lines as written; in OFF (and OBJ from
// another format) the coordinates as the input wrote them, or with round-trip digits.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vrs/simplify.h"

namespace vrs_tool {

class ExactVertices {
 public:
  // Reads `input` (.ply, .obj, .off) again when `output` could lose something, keeping only
  // what is needed: needed() is false (nothing kept) for a float binary PLY written as binary
  // PLY, or an OBJ of float-exact coordinates written as OBJ, and for other formats.
  ExactVertices(const std::string& input, const std::string& output, bool ascii_output);
  bool needed() const { return needed_; }
  // Coordinates a float cannot hold: the core takes core_positions().
  bool has_double_positions() const { return beyond_float_; }
  // The core's positions: the input's, less the first vertex's (so floats keep the detail).
  // False when the file does not hold `vertices` vertices (vcglib read something else).
  bool core_positions(size_t vertices, std::vector<float>& out) const;
  // Rewrites the vertices of the file written at `written` into `output`, from the input
  // vertices `kept` names (output vertex -> input vertex): a PLY's vertex element with the
  // input's property lines and records, converted to the written encoding; the coordinates of
  // an OFF's or OBJ's vertex lines (an OBJ's whole `v` line from an OBJ). "" or what went wrong.
  std::string rewrite(const std::string& written, const std::string& output,
                      const std::vector<uint32_t>& kept) const;

 private:
  std::string in_format_, out_format_;
  bool needed_ = false, beyond_float_ = false, ascii_in_ = false, big_in_ = false;
  std::string coords_;                  // text outputs: each vertex's "x y z" (or OBJ v line)
  std::vector<uint64_t> coord_offsets_; // vertex v: coords_[coord_offsets_[v], ...[v + 1])
  std::string rewrite_text(const std::string& written, const std::string& output,
                           const std::vector<uint32_t>& kept) const;
  std::vector<std::string> props_; // the input's vertex property lines
  std::vector<int> types_;         // each property's type (see the .cpp)
  std::vector<double> xyz_;        // when beyond_float_
  std::string records_;            // every vertex's record, as read
  std::vector<uint64_t> offsets_;  // record v: records_[offsets_[v], offsets_[v + 1])
};

} // namespace vrs_tool
