// The driver: read -> classify + evaluate -> queue -> pop -> plan -> commit -> re-evaluate the
// ring -> ... -> compact. Decisions live in the modules it calls (simplifier.h lists where each
// step lives); this file only sequences them.
#include "driver/simplifier.h"

#include <chrono>
#include <limits>

#include "mesh/input_check.h"
#include "queue/bucket_queue.h"
#include "queue/heap_queue.h"
#include "write/output.h"

namespace vrs {

bool Simplifier::target_met() const {
  switch (opt_.target.kind) {
  case TargetKind::Faces:
  case TargetKind::Ratio: return faces_ <= target_faces_;
  case TargetKind::Vertices: return vertices_ <= target_vertices_;
  default: return false;
  }
}

float Simplifier::progress_fraction(size_t queued, size_t queued0) const {
  double f = 0;
  switch (opt_.target.kind) {
  case TargetKind::Faces:
  case TargetKind::Ratio:
    f = faces0_ > target_faces_ ? double(faces0_ - faces_) / double(faces0_ - target_faces_) : 1;
    break;
  case TargetKind::Vertices: {
    size_t v0 = vertices_ + rep_.removed;
    f = v0 > target_vertices_ ? double(rep_.removed) / double(v0 - target_vertices_) : 1;
    break;
  }
  default: f = queued0 ? 1.0 - double(queued) / double(queued0) : 1; break;
  }
  return static_cast<float>(std::min(1.0, std::max(0.0, f)));
}

template <class Queue> void Simplifier::run(Queue& queue) {
  const size_t n = mesh_.vertex_count();
  IntervalMap map;
  map.n = opt_.tuning.intervals;
  map.kind = opt_.tuning.mapping;
  const bool by_factor = opt_.target.kind == TargetKind::MaxFactor;
  // In the input's order, as the paper fills its table: the FIFO of an interval then follows
  // the input, not space, and removals spread over the mesh. The candidates and the highest
  // price are found in blocks on the workers (scattered reads: after the parts most vertices
  // are gone), then placed in the table in that order, also on the workers.
  constexpr size_t kBlock = 65536;
  std::vector<std::vector<uint32_t>> found((n + kBlock - 1) / kBlock);
  std::vector<double> highest(found.size(), 0.0);
  for_each_block(&workers_, n, kBlock, [&](size_t begin, size_t end) {
    auto& out = found[begin / kBlock];
    double& f_max = highest[begin / kBlock];
    for (size_t i = begin; i < end; ++i) {
      if (std::isfinite(priority_[i])) f_max = std::max(f_max, double(priority_[i]));
      const uint32_t v = queue_order(i);
      if (std::isfinite(priority_[v]) && (!by_factor || priority_[v] <= opt_.target.max_factor))
        out.push_back(v);
    }
  });
  for (double f : highest)
    map.f_max = std::max(map.f_max, f);
  queue.init(n, map, &workers_);
  batch_.resize(kBatch);
  batch_ids_.resize(kBatch);
  queue.fill(found, priority_.data(), &workers_);

  const size_t queued0 = queue.size();
  const bool counts = opt_.target.kind == TargetKind::Faces ||
                      opt_.target.kind == TargetKind::Ratio ||
                      opt_.target.kind == TargetKind::Vertices;
  size_t pops_since_respread = 0, since_progress = 0;
  for (;;) {
    if (target_met()) {
      rep_.stop = StopReason::TargetReached;
      break;
    }
    if (queue.empty() && counts && opt_.relax_to_reach_target && relax(queue, false)) continue;
    if (queue.empty()) {
      // With a finite error bound that refused removals, the bound is what stopped the run.
      const bool bounded = std::isfinite(opt_.max_error) && rep_.rejected[RejectBound] > 0;
      rep_.stop = by_factor ? StopReason::MaxFactor
                  : bounded ? StopReason::ErrorBound
                  : counts  ? StopReason::NoCandidates
                            : StopReason::LastInterval;
      break;
    }
    if (queue.only_last_left()) {
      if (!counts && !by_factor) {
        rep_.stop = StopReason::LastInterval;
        break;
      }
      // A count target asks for more than the table's range allows: spread the remaining
      // vertices over a new range. Amortized: at most once per quarter of the queue popped.
      if (pops_since_respread >= queue.size() / 4) {
        queue.respread(priority_.data());
        pops_since_respread = 0;
      }
    }
    if (opt_.progress && since_progress >= 256 &&
        !opt_.progress(progress_fraction(queue.size(), queued0))) {
      rep_.stop = StopReason::Cancelled;
      break;
    }

    // Read a batch off the front and plan it on the workers against today's mesh; then take
    // each in queue order as if popped alone: refused, pushed back (a stale price that no
    // longer leads) or committed. A plan holds only while no removal of the batch touched a
    // vertex in or next to its own: one that did is left at the front for the next batch.
    const size_t count = take_front(queue, batch_ids_, batch_from_);
    plan_batch(count, queue);
    since_progress = since_progress >= 256 ? count : since_progress + count;
    for (size_t b = 0; b < count && !target_met(); ++b) {
      Planned& p = batch_[b];
      const uint32_t v = p.v;
      if (!taken_.holds(flags_, v, p.ring)) continue;
      queue.erase(v);
      flags_[v] &= ~kFlagStale;
      ++pops_since_respread;
      if (!p.usable) continue;
      set_refused(v, p.why);
      if (p.why != RejectCount) {
        ++rep_.rejected[p.why]; // retried when a neighbour's removal changes its ring
        continue;
      }
      if (p.stale) { // its price is today's only now: it goes only if it still leads
        priority_[v] = static_cast<float>(p.priority);
        if (by_factor && !(p.priority <= opt_.target.max_factor)) continue;
        if (!queue.still_cheapest(p.priority, p.from)) {
          queue.push(v, p.priority);
          continue;
        }
      }
      if (counts && jumps(p.stale ? p.priority : double(priority_[v]))) {
        // The cheapest removal left is far dearer than any so far: not at any cost (below).
        jump_price_ = p.stale ? p.priority : double(priority_[v]);
        jump_from_ = jump_base();
        queue.push(v, jump_price_);
        break;
      }
      taken_.mark(flags_, v, p.ring);
      account(p, queue);
      committed_.push_back(uint32_t(b));
    }
    taken_.clear(flags_);
    workers_.for_each(committed_.size(), [&](size_t i) { rewrite(batch_[committed_[i]]); });
    for (uint32_t b : committed_)
      for (int i = 0; i < batch_[b].overflows; ++i)
        topo_.add_face(batch_[b].overflow[i].first, batch_[b].overflow[i].second);
    committed_.clear();
    reprice(queue);
    // Most of what is left refused only by a corner's input normal (threads, thin walls,
    // tunnels): take those, one corner facing away allowed, before the cheapest rest drops a
    // part.
    if (counts && !eased() && opt_.relax_to_reach_target && flip_refused_ > queue.size() &&
        relax(queue, false))
      continue;
    if (jump_price_ > 0) {
      if (opt_.relax_to_reach_target && relax(queue, true)) {
        jump_price_ = 0;
        continue;
      }
      rep_.stop = StopReason::NoCandidates;
      break;
    }
  }
  if (opt_.progress && rep_.stop != StopReason::Cancelled) opt_.progress(1.0f);
}

Options priced_as_input(Options options, size_t input_faces) {
  if (input_faces >= options.tuning.lazy_from_faces)
    options.tuning.lazy_from_faces = 0; // lazy whatever the piece's size
  else
    options.tuning.lazy_reevaluation = false; // eager whatever the piece's size
  return options;
}

Report simplify(Mesh& mesh, const Options& options) {
  return simplify_recorded(mesh, options, nullptr);
}

Report simplify_recorded(Mesh& mesh, const Options& options, RemovalRecord* record,
                         RunProjection* projection) {
  Report rep;
  rep.input_vertices = mesh.vertex_count();
  rep.input_faces = mesh.face_count();
  rep.vertices = rep.input_vertices;
  rep.faces = rep.input_faces;
  std::string error = check_mesh(mesh);
  if (error.empty()) error = check_options(options, mesh.vertex_count(), mesh.face_count());
  if (!error.empty()) {
    rep.message = error;
    return rep;
  }

  const auto start = std::chrono::steady_clock::now();
  Simplifier s(mesh, options, rep);
  if (record) s.record_removals(&record->log);
  s.prepare();
  if (!s.run_parts()) {
    // cancelled while the parts ran
  } else if (options.tuning.queue == QueueKind::Heap) {
    HeapQueue q;
    s.run(q);
  } else {
    BucketQueue q;
    s.run(q);
  }
  if (rep.stop == StopReason::NoCandidates || rep.stop == StopReason::ErrorBound) s.explain_stop();
  if (rep.stop != StopReason::Cancelled) s.slide();
  if (record) s.standing_faces(record->base_slots, record->base_corners);
  s.compact();
  rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rep.parallel_seconds = s.parallel_seconds();
  if (projection) {
    projection->seconds_8 = rep.seconds - rep.parallel_seconds + s.span_seconds(8);
    projection->seconds_16 = rep.seconds - rep.parallel_seconds + s.span_seconds(16);
  }
  rep.ok = true;
  rep.target_reached = rep.stop == StopReason::TargetReached || rep.stop == StopReason::MaxFactor ||
                       rep.stop == StopReason::LastInterval || rep.stop == StopReason::ErrorBound;
  rep.message = input_warnings(rep);
  return rep;
}

} // namespace vrs
