// The parts of a .glb file every writer shares: padding, index bytes, the file itself.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace vrs {

inline size_t pad4(size_t n) {
  return (n + 3) & ~size_t(3);
}

void put_u32(std::vector<uint8_t>& out, uint32_t x);

// Indices as bytes: 16 bits when `vertices` allow (65535 is the primitive restart value glTF
// forbids as an index), else 32 (`wide`); padded to 4 bytes.
std::vector<uint8_t> index_bytes(const std::vector<uint32_t>& idx, size_t vertices, bool& wide);

// Writes header, `json` (padded with spaces) and a binary chunk of `pieces` in order (each
// padded with zeros to 4 bytes) to `path`, whole or not at all (a temporary file renamed).
// `json_bytes`: the JSON chunk's padded length. Empty string on success, else the error.
std::string write_glb_file(const std::string& path, const std::string& json,
                           const std::vector<const std::vector<uint8_t>*>& pieces,
                           size_t* json_bytes = nullptr);

} // namespace vrs
