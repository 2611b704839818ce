// The driver's per-vertex state bits, one byte a vertex (its pieces share the array).
#pragma once

#include <cstdint>

#include "vrs/simplify.h"

namespace vrs {

constexpr uint8_t kFlagLocked = 1;  // never removed: user lock, or next to a NaN/inf position
constexpr uint8_t kFlagRemoved = 2; // gone from the mesh
constexpr uint8_t kFlagStale = 32;  // queued with a price from before its ring last changed
constexpr uint8_t kFlagTaken = 64;  // in or next to a vertex removed in the current batch
// With kFlagLocked: a border vertex at another's exact position, kept when the border is
// simplified (Simplifier::lock_split_seams).
constexpr uint8_t kFlagTwin = 128;
// Bits 2-4: the vertex's last plan's Reject (RejectCount: none), for Report::stop_detail.
constexpr int kRefusedShift = 2;
constexpr uint8_t kRefusedMask = 7 << kRefusedShift;
static_assert(RejectCount <= 7, "a Reject must fit the flag bits");

} // namespace vrs
