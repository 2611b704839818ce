// A PLY input's vertices as the file holds them, so that the in-core run keeps them untouched
// where vcglib's mesh (float) cannot: coordinates stored as double (a georeferenced terrain at
// x ~ 500 000, y ~ 4 100 000 m, where a float steps by 0.25-0.5 m), and ascii output (vcglib
// prints 6 or 7 digits). The core takes its positions from the doubles, from the first vertex
// on (float then holds the mesh's own detail); the PLY output's vertex element is then
// rewritten from the input's records — every property in its own type, bit for bit in binary,
// with round-trip digits in ascii (9 significant for float, 17 for double).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vrs/simplify.h"

namespace vrs_tool {

class ExactVertices {
 public:
  // Reads `ply` again, keeping nothing unless needed: `needed()` is false (and nothing is kept)
  // when the input is not a PLY, has no double vertex property and `ascii_output` is false, or
  // has list properties on its vertices.
  ExactVertices(const std::string& ply, bool ascii_output);
  bool needed() const { return needed_; }
  bool has_double_positions() const { return double_positions_; }
  // The core's positions: the input's, less the first vertex's (so floats keep the detail).
  // False when the file does not hold `vertices` vertices (vcglib read something else).
  bool core_positions(size_t vertices, std::vector<float>& out) const;
  // Rewrites the vertex element of the PLY vcglib wrote at `written` (binary little endian or
  // ascii) into `output`, with the input's property lines and the records of the input
  // vertices `kept` names (output vertex -> input vertex), converted to the written encoding.
  // "" or what went wrong.
  std::string rewrite(const std::string& written, const std::string& output,
                      const std::vector<uint32_t>& kept) const;

 private:
  bool needed_ = false, double_positions_ = false, ascii_in_ = false, big_in_ = false;
  std::vector<std::string> props_; // the input's vertex property lines
  std::vector<int> types_;         // each property's type (see the .cpp)
  std::vector<double> xyz_;        // when double_positions_
  std::string records_;            // every vertex's record, as read
  std::vector<uint64_t> offsets_;  // record v: records_[offsets_[v], offsets_[v + 1])
};

} // namespace vrs_tool
