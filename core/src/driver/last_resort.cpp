#include "driver/simplifier.h"
#include "queue/bucket_queue.h"
#include "queue/heap_queue.h"

namespace vrs {

template <class Queue> bool Simplifier::relax(Queue& queue, bool after_jump) {
  // A jump is met once by letting one corner disagree; the last resort is for a queue run dry.
  if (last_resort() || (after_jump && eased())) return false;
  // Nothing to gain when the kept border alone needs more than the target: on the input's
  // surface (Euler, manifold), any triangulation keeping its B border vertices has at least
  // 2B - 2V + F faces. Lifting vetoes there would only crumple the interior.
  if (!simplify_boundary_ && rep_.kept_boundary &&
      border_takes(rep_.kept_boundary, vertices_ + rep_.removed, 1.0))
    return false;
  // First step (when most of the queue's rest is refused by a corner's input normal, at a
  // price jump, or when the queue runs dry): a new triangle may face away from the input's
  // normal at one of its three corners. Thin parts, threads and tunnels are where every
  // filling has such a corner: better taken than a part dropped. Allowed from the start, it
  // crossed CAD creases for nothing at 50 %.
  // The last resort, in one place: the input normals asked of one corner of a new triangle
  // only, the outline corners (the evaluation's setting) and, through removable(), the single
  // triangles; and where every filling is refused, the least-cost one is tried. The fold-over
  // vetoes stay: where only folding fillings are left, the run stops and says so.
  // Each step queues every removable vertex again; one that leaves nothing queued goes on to
  // the next (after a jump, only the first is taken).
  // What the eased corner test no longer holds, the input itself does: from the first step on,
  // no new triangle may turn more than 90 degrees from the input face nearest it (the fold-over
  // as the benchmark measures it). Before, only triangles over two input faces whose corners'
  // normals are unsure answer to it (removal.cpp): asked of every plan it cost threaded parts
  // their thread at 10 %. Asked once eased, it keeps small outputs from folding (a plate with
  // 16 tunnels stops clean instead of crumpling); the price of a jump is measured from the
  // removals before the easing.
  if (!eased()) relaxed_from_ = rep_.max_removed_factor;
  // One switch for both sides: the input judges every new triangle (removal.cpp), the faces
  // replaced no longer do (vetoes.cpp). Only where the input is kept: not when the target is
  // asked at any cost.
  limits_.folds_judged_by_input = input_.kept();
  do {
    if (!eased() && limits_.agreeing_corners > 2) {
      relax_level_ = RelaxLevel::Eased;
      limits_.agreeing_corners = 2;
    } else {
      if (after_jump) { // eased, not the last resort: a jump is met once
        relax_level_ = RelaxLevel::Eased;
        return false;
      }
      relax_level_ = RelaxLevel::LastResort;
      limits_.agreeing_corners = 1;
      limits_.least_cost_filling = true;
      eval_.set_boundary_corner_cos(-1.0);
    }
    requeue(queue);
  } while (queue.empty() && !last_resort());
  return !queue.empty();
}

template <class Queue> void Simplifier::requeue(Queue& queue) {
  Ring ring;
  const uint32_t* tris = mesh_.triangles.data();
  for (uint32_t i = 0; i < mesh_.vertex_count(); ++i) {
    const uint32_t v = queue_order(i); // as run() queues
    if (flags_[v] & (kFlagLocked | kFlagRemoved) || topo_.valence(v) == 0) continue;
    if (!removable(topo_.ring(v, tris, opt_.max_valence, ring))) continue;
    const Priced p = evaluate(v, ring);
    note(v, p);
    priority_[v] = static_cast<float>(p.priority);
    flags_[v] &= ~kFlagStale;
    if (queue.contains(v)) queue.erase(v);
    if (std::isfinite(p.priority)) queue.push(v, p.priority);
  }
}

template bool Simplifier::relax(BucketQueue&, bool);
template void Simplifier::requeue(BucketQueue&);
template void Simplifier::requeue(HeapQueue&);
template bool Simplifier::relax(HeapQueue&, bool);

} // namespace vrs
