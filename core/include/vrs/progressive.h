// A progressive mesh from one run: the simplified mesh (the base) and, coarsest first, one
// insertion a removed vertex. An insertion undoes a removal: the vertex comes back and its fan
// of faces replaces the patch that filled its hole. Applied in order, the insertions rebuild
// the input face by face; any prefix of them is a mesh of the run's sequence.
//
// Faces live in slots, one an input face: the removal of a vertex wrote its patch into the
// slots of its fan's faces (the rest emptied), so its insertion writes the fan's faces back
// into those slots. After every insertion, slot f holds input face f again.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vrs/simplify.h"

namespace vrs {

struct ProgressiveMesh {
  bool ok = false;
  std::string message; // the error when not ok
  Report report;       // of the run that made the base (no slide: every removal is undone)
  // Corners name input corners (3 * input face + corner): the vertex a corner draws is the
  // input's triangles[corner], its per-corner data that input corner's.
  std::vector<uint32_t> base_slots;   // the base mesh's faces: their slots, increasing
  std::vector<uint32_t> base_corners; // 3 a base face
  // Insertion i writes faces [first[i], first[i + 1]) (first has one entry more).
  std::vector<uint32_t> vertex; // the input vertex insertion i brings back
  std::vector<uint32_t> first;
  std::vector<uint32_t> slots;   // per written face: its slot
  std::vector<uint32_t> corners; // 3 a written face
  size_t insertion_count() const { return vertex.size(); }
};

// Simplifies `input` with `options` (on one thread, without the slide, which would move a kept
// vertex after the removals that are recorded) and records the insertions. `corner_keys`
// (optional, one per input corner: equal keys = same per-corner data) makes the edges across
// which they differ seams that the base and every prefix keep.
ProgressiveMesh simplify_progressive(const Mesh& input, const Options& options,
                                     const std::vector<uint32_t>* corner_keys = nullptr);

constexpr uint32_t kEmptySlot = 0xffffffffu;

// The faces after the base and insertions [0, count): 3 corners a slot of `slot_count`
// (the input's face count), kEmptySlot in the three corners of an empty slot.
std::vector<uint32_t> apply_insertions(const ProgressiveMesh& p, size_t slot_count, size_t count);

} // namespace vrs
