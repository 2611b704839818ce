#include "driver/scheduler.h"

#include <atomic>

#include "driver/accounting.h"
#include "driver/simplifier.h"
#include "queue/bucket_queue.h"
#include "queue/heap_queue.h"

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

// Each plan reads memory scattered over the mesh (a batch follows the queue, not space), so
// what the next steps will read is asked for ahead: the next plans' vertex lists and faces, a
// plan's ring vertices' lists, normals and faces for its vetoes, and what the serial
// accounting will read of an accepted plan (found then in the shared cache). Together they
// saved about a sixth of the time on one thread at 1.2 M faces, and the last one an eighth
// of the two-thread time at 4.8 M.
void Simplifier::plan_removal(Planned& p, bool areas) const {
  const bool local = opt_.tuning.priority == Priority::LocalError;
  const uint32_t* tris = mesh_.triangles.data();
  p.stale = flags_[p.v] & kFlagStale;
  p.why = RejectCount;
  p.usable = removable(topo_.ring(p.v, tris, opt_.max_valence, p.ring));
  if (!p.usable) return;
  for (int i = 0; i < p.ring.verts; ++i) {
    topo_.prefetch_list(p.ring.v[i]);
    prefetch(&normals_[4 * size_t(p.ring.v[i])]);
  }
  double chord = 0, cost = 0;
  Evaluation e = evaluate_plane(p.v, p.ring, &chord);
  for (int i = 0; i < p.ring.verts; ++i)
    topo_.prefetch_faces(p.ring.v[i], tris);
  if (!std::isfinite(e.factor)) {
    p.usable = false;
    return;
  }
  // The plan is made again: a diagonal may have become an edge since v was queued. Only a
  // stale price is made again.
  p.why = plan(p.v, p.ring, e, p.patch, cost, /*check_topology=*/true, p.stale && local,
               /*hinted=*/!p.stale, p.lead);
  p.priority = local ? std::max(cost, chord) : e.factor;
  if (areas && p.why == RejectCount && lazy_) fan_area_changes(p.ring, p.patch, p.area_change);
}

template <class Queue> void Simplifier::plan_batch(size_t count, const Queue& queue) {
  // One plan a chunk: most batches of the whole queue's last removals hold a few plans (5 358
  // of 6 885 at 1.2 M faces held four or fewer), which a grain of 4 left on one thread.
  // A plan that needs the input's hierarchy before it is built waits (InputSurface::Deferral):
  // it is built on all the workers, and those plans are made again, with the hints they
  // started from: the plans they would have been.
  const uint32_t* tris = mesh_.triangles.data();
  std::atomic<bool> deferred{false};
  auto plan_one = [&](size_t b) {
    Planned& p = batch_[b];
    p.v = batch_ids_[b];
    p.from = batch_from_;
    if (b + 2 < count) topo_.prefetch_list(batch_ids_[b + 2]);
    if (b + 1 < count) topo_.prefetch_faces(batch_ids_[b + 1], tris);
    const uint8_t hint = lazy_ ? chosen_[p.v] : 0;
    InputSurface::Deferral wait;
    plan_removal(p);
    p.deferred = wait.wanted();
    if (p.deferred) {
      if (lazy_) chosen_[p.v] = hint;
      deferred.store(true, std::memory_order_relaxed);
      return;
    }
    if (!p.usable || p.why != RejectCount) return;
    for (int i = -1; i < p.ring.verts; ++i) {
      const uint32_t u = i < 0 ? p.v : p.ring.v[i];
      queue.prefetch(u);
      prefetch(&flags_[u]);
      prefetch(&priority_[u]);
      if (lazy_) prefetch(&fan_area_[u]);
    }
  };
  workers_.for_each(count, plan_one, /*grain=*/1);
  if (!deferred.load(std::memory_order_relaxed)) return;
  input_.build_on(eval_, &workers_);
  for (size_t b = 0; b < count; ++b)
    if (batch_[b].deferred) plan_one(b); // few: on the caller
}

template void Simplifier::plan_batch(size_t, const BucketQueue&);
template void Simplifier::plan_batch(size_t, const HeapQueue&);

} // namespace vrs
