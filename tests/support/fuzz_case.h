// The fuzzer's input format: bytes -> a mesh and options, the run and every check. Shared by
// the libFuzzer target (fuzz/), its seed maker and the regression test of its findings.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "vrs/simplify.h"

namespace vrs_test {

struct FuzzCase {
  vrs::Mesh mesh;
  vrs::Options options; // progress is set by run_fuzz_case when cancel_after > 0
  int cancel_after = 0; // progress calls before the callback says stop (0: no callback)
  std::vector<uint8_t> locks;
  std::vector<uint32_t> constraints; // constrained edges (pairs), with corner sources asked
};

// Layout: 2 flag bytes (target kind, mode, queue, mapping, boundary, priority, raw indices,
// locks, cancel, unchecked options, constrained edges, creases, projection fill),
// intervals (u16), max valence (u8), target parameter (u32),
// cancel count (u8), lock stride (u8), vertex count (u16), the positions as raw floats (any
// bit pattern: NaN, inf, huge), then triangles as u16 triples until the bytes run out.
// Indices are taken modulo vertex count + 1 (so one past the end still occurs) unless the raw
// flag is set. Short input is padded with zeros: every byte string is a case.
FuzzCase decode_fuzz_case(const uint8_t* data, size_t size);
// The inverse for a valid mesh (seeds); `flags` are the first two bytes.
std::vector<uint8_t> encode_fuzz_case(const vrs::Mesh& m, uint8_t flags0, uint8_t flags1,
                                      uint16_t intervals, uint32_t target_param);

// Decodes, simplifies twice (the two results must be identical) and checks every invariant
// (check_run). "" when all hold, else what broke.
std::string run_fuzz_case(const uint8_t* data, size_t size);

} // namespace vrs_test
