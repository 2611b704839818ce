#include "driver/accounting.h"

#include "driver/parts.h"
#include "driver/simplifier.h"
#include "queue/bucket_queue.h"
#include "queue/heap_queue.h"

namespace vrs {

void fan_area_changes(const Ring& ring, const Patch& patch,
                      std::array<double, kMaxRing + 1>& change) {
  const int k = ring.verts;
  const auto& q = patch.q;                // the ring's positions
  const auto& old_area = patch.face_area; // each old face's, made with the plan
  std::array<double, kMaxRing> new_area;  // each new face's, made once
  for (int t = 0; t < patch.count; ++t)
    new_area[t] = triangle_area(q[patch.tri[t][0]], q[patch.tri[t][1]], q[patch.tri[t][2]]);
  for (int i = 0; i < k; ++i) {
    double old_faces = 0, new_faces = 0;
    // Ring face f holds ring vertices f and f + 1: vertex i was in faces i - 1 and i.
    const int before = i > 0 ? i - 1 : ring.closed() ? k - 1 : -1;
    for (int f : {before, i})
      if (f >= 0 && f < ring.faces) old_faces += old_area[f];
    for (int t = 0; t < patch.count; ++t) {
      const auto& tri = patch.tri[t];
      if (tri[0] == i || tri[1] == i || tri[2] == i) new_faces += new_area[t];
    }
    change[i] = new_faces - old_faces;
  }
}

template <class Queue> void Simplifier::account(const Planned& p, Queue& queue) {
  const uint32_t v = p.v;
  const Ring& ring = p.ring;
  std::array<int, 2> seam;
  if (along(v, ring, seam) == Along::Seam) constraints_.merge(v, ring.v[seam[0]], ring.v[seam[1]]);
  flags_[v] |= kFlagRemoved;
  faces_ -= static_cast<size_t>(ring.faces - p.patch.count);
  --vertices_;
  ++rep_.removed;
  rep_.relaxed_removals += eased();
  rep_.max_removed_factor = std::max(rep_.max_removed_factor, double(priority_[v]));
  touch_ring(p, queue, reprice_, nullptr);
}

template <class Queue>
void Simplifier::touch_ring(const Planned& p, Queue& queue, std::vector<uint32_t>& reprice,
                            const uint8_t* frozen) {
  // The neighbours' planes and rings changed. Queued ones are priced again when popped (lazy);
  // the others (refused, or kept until now) are evaluated now and appended to the back of
  // their interval, as every neighbour is with eager re-evaluation. Frozen ones (next to
  // another part while the parts run) are priced when the parts are done.
  const Ring& ring = p.ring;
  const auto& area_change = p.area_change; // made on the workers with the plan
  for (int i = 0; i < ring.verts; ++i) {
    const uint32_t u = ring.v[i];
    const float before = lazy_ ? fan_area_[u] : 0.0f;
    if (lazy_) fan_area_[u] = static_cast<float>(before + area_change[i]);
    if (flags_[u] & kFlagLocked) continue;
    if (frozen && frozen[u]) {
      flags_[u] |= kFlagStale;
    } else if (lazy_ && queue.contains(u)) {
      // Stale: priced again when popped. Meanwhile its place follows the part of its price
      // known without a plan: the local error weighs distances by sqrt(fan area), and the
      // fan's area just changed (the distances are taken as they were). Left in place, a
      // neighbour whose price fell waits behind where it belongs.
      flags_[u] |= kFlagStale;
      if (before > 0 && fan_area_[u] > 0) {
        priority_[u] = static_cast<float>(priority_[u] * std::sqrt(fan_area_[u] / before));
        queue.update(u, priority_[u]);
      }
    } else {
      reprice.push_back(u);
    }
  }
}

template <class Queue> void Simplifier::reprice(Queue& queue) {
  // A vertex is next to at most one removal of a batch, so the list has no repeats, and each
  // price reads only the vertex's own ring.
  repriced_.resize(reprice_.size());
  // A price is a plan: one a chunk, as the batch's (scheduler.cpp).
  workers_.for_each(
      reprice_.size(), [&](size_t i) { repriced_[i] = price_now(reprice_[i]); }, 1);
  const bool by_factor = opt_.target.kind == TargetKind::MaxFactor;
  for (size_t i = 0; i < reprice_.size(); ++i) {
    const uint32_t u = reprice_[i];
    const double f = repriced_[i].priority;
    note(u, repriced_[i]);
    priority_[u] = static_cast<float>(f);
    flags_[u] &= ~kFlagStale;
    if (std::isfinite(f) && (!by_factor || f <= opt_.target.max_factor))
      queue.push(u, f);
    else
      queue.erase(u);
  }
  reprice_.clear();
}

template void Simplifier::account(const Planned&, BucketQueue&);
template void Simplifier::account(const Planned&, HeapQueue&);
template void Simplifier::reprice(BucketQueue&);
template void Simplifier::reprice(HeapQueue&);
template void Simplifier::touch_ring(const Planned&, PartQueue&, std::vector<uint32_t>&,
                                     const uint8_t*);

} // namespace vrs
