#include "scheduler.h"

#include "accounting.h"
#include "bucket_queue.h"
#include "heap_queue.h"
#include "simplifier.h"

namespace vrs {

bool TakenMarks::holds(const std::vector<uint8_t>& flags, uint32_t v, const Ring& ring) const {
  if (flags[v] & kFlagTaken) return false;
  for (int i = 0; i < ring.verts; ++i)
    if (flags[ring.v[i]] & kFlagTaken) return false;
  return true;
}

void TakenMarks::mark(std::vector<uint8_t>& flags, uint32_t v, const Ring& ring) {
  for (int i = -1; i < ring.verts; ++i) {
    const uint32_t u = i < 0 ? v : ring.v[i];
    if (!(flags[u] & kFlagTaken)) flags[u] |= kFlagTaken, marked_.push_back(u);
  }
}

void TakenMarks::clear(std::vector<uint8_t>& flags) {
  for (uint32_t u : marked_)
    flags[u] &= uint8_t(~kFlagTaken);
  marked_.clear();
}

template <class Queue> void Simplifier::plan_batch(size_t count, const Queue& queue) {
  const bool local = opt_.priority == Priority::LocalError;
  workers_.for_each(count, [&](size_t b) {
    Planned& p = batch_[b];
    p.v = batch_ids_[b];
    p.from = batch_from_;
    // Each plan reads scattered memory (the batch follows the queue, not space): the next
    // ones' lists and faces are asked for ahead, in two stages (5 % of the run at 1.2 M).
    if (b + 2 < count) topo_.prefetch_list(batch_ids_[b + 2]);
    if (b + 1 < count) topo_.prefetch_faces(batch_ids_[b + 1], mesh_.triangles.data());
    p.stale = flags_[p.v] & kFlagStale;
    p.why = RejectCount;
    p.usable = removable(topo_.ring(p.v, mesh_.triangles.data(), opt_.max_valence, p.ring));
    if (!p.usable) return;
    // The topology vetoes will read the ring vertices' faces: their lists now, their faces
    // once the plane is made.
    for (int i = 0; i < p.ring.verts; ++i) {
      topo_.prefetch_list(p.ring.v[i]);
      prefetch(&normals_[3 * size_t(p.ring.v[i])]);
    }
    double chord = 0, cost = 0;
    Evaluation e = evaluate_plane(p.v, p.ring, &chord);
    for (int i = 0; i < p.ring.verts; ++i)
      topo_.prefetch_faces(p.ring.v[i], mesh_.triangles.data());
    if (!std::isfinite(e.factor)) {
      p.usable = false;
      return;
    }
    // The plan is made again: a diagonal may have become an edge since v was queued. Only a
    // stale price is made again.
    p.why = plan(p.v, p.ring, e, p.patch, cost, /*check_topology=*/true, p.stale && local);
    p.priority = local ? std::max(cost, chord) : e.factor;
    if (p.why != RejectCount) return;
    if (lazy_) fan_area_changes(eval_.position(p.v), p.ring, p.patch, p.area_change);
    for (int i = -1; i < p.ring.verts; ++i) {
      const uint32_t u = i < 0 ? p.v : p.ring.v[i];
      queue.prefetch(u);
      prefetch(&flags_[u]);
      prefetch(&factor_[u]);
      if (lazy_) prefetch(&fan_area_[u]);
    }
  });
}

template void Simplifier::plan_batch(size_t, const BucketQueue&);
template void Simplifier::plan_batch(size_t, const HeapQueue&);

} // namespace vrs
