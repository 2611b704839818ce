// A planned removal written into the mesh: the ring's faces give way to the patch's, in the
// same slots, with their per-corner data and error bounds; the vertex lists follow.
#include "driver/simplifier.h"

namespace vrs {

void Simplifier::rewrite(Planned& p) {
  const uint32_t v = p.v;
  const Ring& ring = p.ring;
  const Patch& patch = p.patch;
  uint32_t* tris = mesh_.triangles.data();
  if (removal_log_) log_removal(p);
  // Old faces leave their corners' lists; new faces take the first slots (the array never
  // grows: k or k-1 faces out, k-2 in), the rest are marked dead until compaction.
  for (int i = 0; i < ring.faces; ++i) {
    uint32_t f = ring.f[i];
    for (int c = 0; c < 3; ++c)
      if (tris[3 * f + c] != v) topo_.remove_face(tris[3 * f + c], f);
  }
  // Per-corner data of the new faces: the corner of the same vertex in the old face the
  // plan names (read before the slots are overwritten).
  std::array<std::array<uint32_t, 3>, kMaxRing> inherited;
  if (!corner_source_.empty())
    for (int t = 0; t < patch.count; ++t)
      for (int c = 0; c < 3; ++c) {
        uint32_t f = ring.f[patch.from[t][c]], u = ring.v[patch.tri[t][c]];
        int at = tris[3 * f] == u ? 0 : tris[3 * f + 1] == u ? 1 : 2;
        inherited[t][c] = corner_source_[3 * f + at];
      }
  p.overflows = 0;
  for (int i = 0; i < ring.faces; ++i) {
    uint32_t f = ring.f[i];
    order_.face_old[f] |= kRewrittenSlot;
    if (i < patch.count && !face_bound_.empty()) face_bound_[f] = patch.bound[i];
    if (i < patch.count && !corner_source_.empty())
      for (int c = 0; c < 3; ++c)
        corner_source_[3 * f + c] = inherited[i][c];
    for (int c = 0; c < 3; ++c) {
      tris[3 * f + c] = i < patch.count ? ring.v[patch.tri[i][c]] : kNone;
      // A full list grows after the batch, on one thread (growing moves the shared pool).
      if (i < patch.count && !topo_.add_face_in_place(tris[3 * f + c], f))
        p.overflow[p.overflows++] = {tris[3 * f + c], f};
    }
  }
  topo_.clear(v);
  if (carried_.active()) carried_.hand_over(v, ring, patch, eval_);
}

uint32_t Simplifier::slot_label(uint32_t f) const {
  const uint32_t old = order_.face_old[f] & ~kRewrittenSlot;
  return kept_faces_.empty() ? old : kept_faces_[old];
}

void Simplifier::face_corners(uint32_t f, uint32_t out[3]) const {
  std::copy_n(&corner_source_[3 * size_t(f)], 3, out);
  if (!turned_.empty() && turned_[out[0] / 3]) std::swap(out[1], out[2]); // as write_output
}

void Simplifier::log_removal(const Planned& p) {
  const uint32_t* tris = mesh_.triangles.data();
  std::vector<uint32_t>& log = *removal_log_;
  const uint32_t f0 = p.ring.f[0];
  const int at = tris[3 * f0] == p.v ? 0 : tris[3 * f0 + 1] == p.v ? 1 : 2;
  log.push_back(uint32_t(p.ring.faces));
  log.push_back(corner_source_[3 * f0 + at]);
  for (int i = 0; i < p.ring.faces; ++i) {
    const uint32_t f = p.ring.f[i];
    uint32_t corners[3];
    face_corners(f, corners);
    log.insert(log.end(), {slot_label(f), corners[0], corners[1], corners[2]});
  }
}

} // namespace vrs
