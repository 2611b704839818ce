// The progressive mesh (progressive.h): one run with its removals recorded, read backwards.
#include "vrs/progressive.h"

#include <algorithm>
#include <utility>

#include "driver/simplifier.h"
#include "mesh/corner_seams.h"
#include "mesh/input_check.h"

namespace vrs {

void Simplifier::standing_faces(std::vector<uint32_t>& slots,
                                std::vector<uint32_t>& corners) const {
  const std::vector<uint32_t>& t = mesh_.triangles;
  std::vector<std::pair<uint32_t, uint32_t>> standing; // (slot, the run's face)
  for (size_t f = 0; f < t.size() / 3; ++f)
    if (t[3 * f] != kNone) standing.emplace_back(slot_label(uint32_t(f)), uint32_t(f));
  std::sort(standing.begin(), standing.end());
  for (const auto& [slot, f] : standing) {
    uint32_t c[3];
    face_corners(f, c);
    slots.push_back(slot);
    corners.insert(corners.end(), {c[0], c[1], c[2]});
  }
}

ProgressiveMesh simplify_progressive(const Mesh& input, const Options& options,
                                     const std::vector<uint32_t>* corner_keys) {
  ProgressiveMesh out;
  out.message = check_mesh(input);
  if (out.message.empty() && corner_keys && corner_keys->size() != input.triangles.size())
    out.message = "corner keys: one per face corner";
  if (!out.message.empty()) return out;
  // One thread: the removals are recorded in the order they are written. No slide: it moves
  // a kept vertex after the run, which no insertion could undo.
  Options o = options;
  o.threads = 1;
  o.tuning.part_vertices = 0; // one queue: its order is the order of removal of a run to any size
  o.slide = false;
  o.corner_sources = true;
  std::vector<uint32_t> edges =
      options.constrained_edges ? *options.constrained_edges : std::vector<uint32_t>{};
  if (corner_keys) {
    const std::vector<uint32_t> seams = key_seams(input, *corner_keys);
    edges.insert(edges.end(), seams.begin(), seams.end());
  }
  o.constrained_edges = edges.empty() ? nullptr : &edges;
  Mesh mesh = input;
  RemovalRecord record;
  out.report = simplify_recorded(mesh, o, &record);
  if (!out.report.ok) {
    out.message = out.report.message;
    return out;
  }
  out.base_slots = std::move(record.base_slots);
  out.base_corners = std::move(record.base_corners);
  // The log holds the removals first to last; the insertions are they, last to first.
  std::vector<size_t> starts;
  for (size_t at = 0; at < record.log.size(); at += 2 + 4 * size_t(record.log[at]))
    starts.push_back(at);
  out.first.push_back(0);
  for (auto it = starts.rbegin(); it != starts.rend(); ++it) {
    const uint32_t* entry = &record.log[*it];
    out.vertex.push_back(input.triangles[entry[1]]);
    for (uint32_t i = 0; i < entry[0]; ++i) {
      const uint32_t* face = entry + 2 + 4 * i;
      out.slots.push_back(face[0]);
      out.corners.insert(out.corners.end(), {face[1], face[2], face[3]});
    }
    out.first.push_back(uint32_t(out.slots.size()));
  }
  out.ok = true;
  return out;
}

std::vector<uint32_t> apply_insertions(const ProgressiveMesh& p, size_t slot_count, size_t count) {
  std::vector<uint32_t> faces(3 * slot_count, kEmptySlot);
  auto put = [&](uint32_t slot, const uint32_t* corners) {
    if (slot < slot_count) std::copy_n(corners, 3, &faces[3 * size_t(slot)]);
  };
  for (size_t i = 0; i < p.base_slots.size(); ++i)
    put(p.base_slots[i], &p.base_corners[3 * i]);
  count = std::min(count, p.insertion_count());
  for (size_t r = 0; r < count; ++r)
    for (uint32_t j = p.first[r]; j < p.first[r + 1]; ++j)
      put(p.slots[j], &p.corners[3 * size_t(j)]);
  return faces;
}

} // namespace vrs
