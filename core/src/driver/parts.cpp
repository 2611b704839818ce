// Simplification by parts (parts.h): the parts' rounds up to a shared price, then the whole
// mesh's queue takes over in Simplifier::run().
#include "driver/parts.h"

#include <algorithm>
#include <limits>
#include <memory>
#include <utility>

#include "base/workers.h"
#include "driver/accounting.h"
#include "driver/simplifier.h"

namespace vrs {

Parts make_parts(const std::vector<uint32_t>& tris, const Topology& topo, uint32_t size,
                 uint32_t shift, const std::vector<uint32_t>& sibling, Workers* workers) {
  const size_t vertex_count = topo.vertex_count();
  Parts parts;
  parts.size = size;
  parts.shift = shift;
  parts.count = (vertex_count + shift + size - 1) / size;
  // First the vertices on the cut (a face of theirs spans parts), then every vertex of a face
  // holding one of those: a removable vertex's ring then lies in its part and never reaches a
  // vertex whose ring another part may change. Each pass reads the one before and writes its
  // own vertices' bytes only.
  constexpr size_t kBlock = 16384;
  std::vector<uint8_t> cut(vertex_count, 0);
  for_each_block(workers, vertex_count, kBlock, [&](size_t begin, size_t end) {
    for (size_t v = begin; v < end; ++v) {
      if (v < sibling.size() && sibling[v] != kNone) {
        cut[v] = 1;
        continue;
      }
      const uint32_t* f = topo.faces_of(uint32_t(v));
      const size_t part = parts.of(uint32_t(v));
      for (uint32_t i = 0; i < topo.valence(uint32_t(v)) && !cut[v]; ++i)
        for (int c = 0; c < 3; ++c)
          if (parts.of(tris[3 * size_t(f[i]) + c]) != part) cut[v] = 1;
    }
  });
  parts.frozen.assign(vertex_count, 0);
  auto& frozen = parts.frozen;
  for_each_block(workers, vertex_count, kBlock, [&](size_t begin, size_t end) {
    for (size_t v = begin; v < end; ++v) {
      const uint32_t* f = topo.faces_of(uint32_t(v));
      bool near = false;
      for (uint32_t i = 0; i < topo.valence(uint32_t(v)) && !near; ++i)
        for (int c = 0; c < 3; ++c)
          near = near || cut[tris[3 * size_t(f[i]) + c]];
      frozen[v] = uint8_t((cut[v] ? 2 : 0) | (near ? 1 : 0));
    }
  });
  return parts;
}

void PartQueue::init(uint32_t first, size_t count) {
  first_ = first;
  seq_ = 0;
  heap_.clear();
  heap_.reserve(count); // never more entries than vertices: no doubling's slack
  pos_.assign(count, kNone);
}

size_t PartQueue::count_at_most(double f) const {
  size_t count = 0;
  for (const Entry& e : heap_)
    count += e.f <= f;
  return count;
}

// Four children a node: half the levels of a binary heap, and a node's children side by side
// in one or two cache lines. The order is the entries' (price, then push order): the same pops
// whatever the heap's shape.
void PartQueue::sift_up(size_t i) {
  const Entry e = heap_[i];
  for (; i > 0 && less(e, heap_[(i - 1) / 4]); i = (i - 1) / 4)
    place(i, heap_[(i - 1) / 4]);
  place(i, e);
}

void PartQueue::sift_down(size_t i) {
  const Entry e = heap_[i];
  const size_t n = heap_.size();
  for (size_t first; (first = 4 * i + 1) < n;) {
    size_t c = first;
    for (size_t j = first + 1; j < std::min(first + 4, n); ++j)
      if (less(heap_[j], heap_[c])) c = j;
    if (!less(heap_[c], e)) break;
    place(i, heap_[c]);
    i = c;
  }
  place(i, e);
}

void PartQueue::push(uint32_t v, double f) {
  if (contains(v)) erase(v);
  heap_.push_back({float(f), seq_++, v - first_});
  sift_up(heap_.size() - 1);
}

void PartQueue::erase(uint32_t v) {
  const uint32_t i = pos_[v - first_];
  if (i == kNone) return;
  pos_[v - first_] = kNone;
  const Entry last = heap_.back();
  heap_.pop_back();
  if (i == heap_.size()) return;
  place(i, last);
  sift_up(i);
  sift_down(pos_[last.v]);
}

// What one part did in a round, added to the run's counts in part order after it.
struct Simplifier::Part {
  PartQueue queue;
  Topology::Arena arena;
  std::vector<uint32_t> reprice;
  size_t faces_removed = 0, removed = 0;
  double max_factor = 0;
  std::array<size_t, RejectCount> rejected{};
  ptrdiff_t flip_refused = 0;
  bool full = false;  // its arena could not take the next removal's lists: done
  bool waits = false; // a plan asked for the input's hierarchy unbuilt: stopped for the round
};

size_t Simplifier::removals_needed() const {
  if (target_faces_) return faces_ > target_faces_ ? (faces_ - target_faces_) / 2 : 0;
  return vertices_ > target_vertices_ ? vertices_ - target_vertices_ : 0;
}

bool Simplifier::by_parts() const {
  // Not under an error bound (its stop is the run's) nor with the paper's factor (eager,
  // cheap prices: the batches suffice); from four parts up.
  const bool counts = opt_.target.kind == TargetKind::Faces ||
                      opt_.target.kind == TargetKind::Ratio ||
                      opt_.target.kind == TargetKind::Vertices;
  return opt_.tuning.part_vertices > 0 && counts && lazy_ && face_bound_.empty() &&
         mesh_.vertex_count() >= 4 * size_t(opt_.tuning.part_vertices);
}

void Simplifier::run_part(Part& part, double threshold, size_t cap, const uint8_t* frozen) {
  auto owned = std::make_unique<Planned>(); // kilobytes: not on a worker's stack
  Planned& p = *owned;
  constexpr float kInf = std::numeric_limits<float>::infinity();
  InputSurface::Deferral wait; // no part builds the input's hierarchy alone (run_cut does)
  for (size_t done = 0; done < cap && !part.queue.empty() && !part.full;) {
    const uint32_t v = part.queue.front();
    if (part.queue.front_factor() > threshold) break;
    part.queue.erase(v);
    p.v = v;
    p.from = -1;
    // A stale price over this goes back (below): its plan needs no mesh vetoes.
    p.lead = part.queue.empty() ? threshold : std::min(threshold, part.queue.front_factor());
    const uint8_t hint = chosen_[v];
    plan_removal(p, /*areas=*/false); // made below for a removal (most plans are pushed back)
    if (wait.wanted()) {              // the plan is thrown away; the part waits for the next round
      chosen_[v] = hint;
      part.queue.push(v, priority_[v]);
      part.waits = true;
      break;
    }
    flags_[v] &= ~kFlagStale;
    if (!p.usable) {
      priority_[v] = kInf; // queued again when its ring changes, as the whole queue does
      continue;
    }
    part.flip_refused += refuse(v, p.why);
    if (p.why != RejectCount) {
      ++part.rejected[p.why];
      priority_[v] = kInf;
      continue;
    }
    if (p.stale) { // today's price: it goes only if it still leads, and stays under the price
      priority_[v] = static_cast<float>(p.priority);
      if (p.priority > threshold ||
          (!part.queue.empty() && p.priority > part.queue.front_factor())) {
        part.queue.push(v, p.priority);
        continue;
      }
    }
    // The ring's lists grow into the part's arena: enough room, or the part is done.
    size_t room = 0;
    const Ring& ring = p.ring;
    for (int i = 0; i < ring.verts; ++i) {
      int faces = 0;
      for (int t = 0; t < p.patch.count; ++t)
        faces += p.patch.tri[t][0] == i || p.patch.tri[t][1] == i || p.patch.tri[t][2] == i;
      const int gone = (i > 0 || ring.closed()) + (i < ring.faces);
      room += topo_.growth(ring.v[i], topo_.valence(ring.v[i]) - gone + faces);
    }
    if (room > part.arena.end - part.arena.next) {
      part.queue.push(v, priority_[v]);
      part.full = true;
      break;
    }
    fan_area_changes(ring, p.patch, p.area_change);
    flags_[v] |= kFlagRemoved;
    part.faces_removed += size_t(ring.faces - p.patch.count);
    ++part.removed;
    part.max_factor = std::max(part.max_factor, double(priority_[v]));
    priority_[v] = kInf;
    touch_ring(p, part.queue, part.reprice, frozen);
    rewrite(p);
    for (int i = 0; i < p.overflows; ++i)
      topo_.add_face(p.overflow[i].first, p.overflow[i].second, part.arena);
    for (uint32_t u : part.reprice) {
      const Priced priced = price_now(u);
      if (priced.planned) {
        part.flip_refused += refuse(u, priced.why);
        if (priced.why != RejectCount) ++part.rejected[priced.why];
      }
      priority_[u] = static_cast<float>(priced.priority);
      flags_[u] &= ~kFlagStale;
      if (std::isfinite(priced.priority))
        part.queue.push(u, priced.priority);
      else
        part.queue.erase(u);
    }
    part.reprice.clear();
    ++done;
  }
}

bool Simplifier::run_parts() {
  if (!by_parts()) return true;
  // Two cuts, the second shifted by half a part, each in rounds: the second frees most of
  // what the first kept frozen along its borders.
  const size_t needed0 = removals_needed();
  const uint32_t size = uint32_t(opt_.tuning.part_vertices);
  for (uint32_t shift : {0u, size / 2}) {
    Parts parts = make_parts(mesh_.triangles, topo_, size, shift, fans_.sibling, &workers_);
    if (!run_cut(parts, needed0)) return false;
    price_frozen(parts);
  }
  return true;
}

bool Simplifier::run_cut(Parts& parts, size_t needed0) {
  const size_t n = mesh_.vertex_count();
  if (constraints_.active()) // seams merge constraints, a structure all parts share
    for (uint32_t v = 0; v < n; ++v)
      if (constraints_.degree(v) > 0) parts.frozen[v] = 1;
  const uint8_t* frozen = parts.frozen.data();
  std::vector<Part> part(parts.count);
  workers_.for_each(
      parts.count,
      [&](size_t i) {
        const uint32_t first = parts.first(i), end = parts.end(i, n);
        part[i].queue.init(first, end - first);
        for (uint32_t v = first; v < end; ++v)
          if (!frozen[v] && !(flags_[v] & kFlagRemoved) && std::isfinite(priority_[v]))
            part[i].queue.push(v, priority_[v]);
      },
      1);
  std::vector<size_t> arena_sizes(parts.count);
  // Half a slot a vertex a cut: the two cuts take half the room the pool holds in reserve;
  // the rest is for the whole queue (a slot each: the pool reallocated then, 19 MB more peak
  // at 1.2 M faces; a quarter: 26 of 74 parts ran out of room).
  for (size_t i = 0; i < parts.count; ++i)
    arena_sizes[i] = size_t(parts.end(i, n) - parts.first(i)) / 2;
  const auto arenas = topo_.reserve_arenas(arena_sizes);
  for (size_t i = 0; i < parts.count; ++i)
    part[i].arena = arenas[i];

  // Rounds: each takes at most half the removals still needed, up to the price all of them are
  // under, each part its share of that half by its vertices under the price, so the parts
  // spend their faces as one queue would; the whole queue then makes the last and dearest
  // ones. (Up to the price half of them are under, a round took only a fraction of that half:
  // after a neighbour's removal most vertices are dearer and wait, and what the parts leave
  // the whole queue makes at a higher cost a removal.)
  std::vector<float> prices;
  // The price is read off a sample of the vertices (every stride-th), the same for any
  // threads: the whole list's nth_element was a tenth of the serial time.
  const size_t stride = std::max<size_t>(1, n / 65536);
  const size_t samples = (n + stride - 1) / stride;
  constexpr size_t kSampleBlock = 4096;
  std::vector<std::vector<float>> sampled((samples + kSampleBlock - 1) / kSampleBlock);
  for (int round = 0; round < kPartRounds; ++round) {
    const size_t needed = removals_needed();
    if (needed <= needed0 * kPartsLeave) break;
    // The frozen vertices count too (at their last price): left out, the price climbed past
    // them while they waited, and small parts came out with far more error.
    // Read in blocks on the workers (scattered reads: a fifth of the serial time by parts);
    // the k-th price does not depend on the order they are joined in.
    for_each_block(&workers_, samples, kSampleBlock, [&](size_t begin, size_t end) {
      auto& out = sampled[begin / kSampleBlock];
      out.clear();
      for (size_t i = begin; i < end; ++i) {
        const uint32_t v = uint32_t(i * stride);
        if (frozen[v] ? !(flags_[v] & kFlagRemoved) && std::isfinite(priority_[v])
                      : part[parts.of(v)].queue.contains(v))
          out.push_back(priority_[v]);
      }
    });
    prices.clear();
    for (const auto& s : sampled)
      prices.insert(prices.end(), s.begin(), s.end());
    const size_t k = std::min(prices.size(), needed / stride);
    if (k == 0) break;
    std::nth_element(prices.begin(), prices.begin() + (k - 1), prices.end());
    const double threshold = prices[k - 1];
    std::vector<size_t> cap(parts.count);
    workers_.for_each(
        parts.count, [&](size_t i) { cap[i] = part[i].queue.count_at_most(threshold); }, 1);
    size_t under = 0;
    for (size_t c : cap)
      under += c;
    if (under > needed / 2) // shares by integer arithmetic: the same on any threads
      for (size_t& c : cap)
        c = size_t(uint64_t(c) * (needed / 2) / under);
    // Handed out dearest first (the most removals allowed, then the lower index): on many
    // threads the long parts then start in the first round instead of ending the last one. The
    // parts write disjoint vertices and are summed in part order: the same output in any order.
    std::vector<uint32_t> order(parts.count);
    for (size_t i = 0; i < parts.count; ++i)
      order[i] = uint32_t(i);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return cap[a] > cap[b]; });
    workers_.for_each(
        parts.count, [&](size_t j) { run_part(part[order[j]], threshold, cap[order[j]], frozen); },
        1);
    // A part that met a plan needing the input's hierarchy stopped there: built now on all the
    // workers (built inside one part, it kept that part far longer than the others).
    bool waited = false;
    for (Part& q : part)
      waited |= std::exchange(q.waits, false);
    if (waited) input_.build_on(eval_, &workers_);
    size_t removed = 0;
    for (Part& q : part) {
      faces_ -= q.faces_removed;
      vertices_ -= q.removed;
      removed += q.removed;
      rep_.removed += q.removed;
      rep_.max_removed_factor = std::max(rep_.max_removed_factor, q.max_factor);
      for (int r = 0; r < RejectCount; ++r)
        rep_.rejected[r] += q.rejected[r];
      flip_refused_ = size_t(ptrdiff_t(flip_refused_) + q.flip_refused);
      q.faces_removed = q.removed = 0;
      q.rejected.fill(0);
      q.flip_refused = 0;
    }
    if (opt_.progress && !opt_.progress(progress_fraction(0, 0))) {
      rep_.stop = StopReason::Cancelled;
      return false;
    }
    if (!waited && removed < k * stride / 8) break; // the prices rose past what parts may take
  }
  return true;
}

void Simplifier::price_frozen(const Parts& parts) {
  // The frozen vertices next to a removal: priced now, on the workers, for the next cut or
  // the whole queue.
  // Found block by block on the workers, the blocks' lists joined in order.
  constexpr size_t kBlock = 65536;
  const size_t n = mesh_.vertex_count();
  std::vector<std::vector<uint32_t>> found((n + kBlock - 1) / kBlock);
  for_each_block(&workers_, n, kBlock, [&](size_t begin, size_t end) {
    for (size_t v = begin; v < end; ++v)
      if (parts.frozen[v] && flags_[v] & kFlagStale && !(flags_[v] & kFlagRemoved))
        found[begin / kBlock].push_back(uint32_t(v));
  });
  std::vector<uint32_t> stale;
  for (const auto& f : found)
    stale.insert(stale.end(), f.begin(), f.end());
  std::vector<Priced> priced(stale.size());
  workers_.for_each(stale.size(), [&](size_t i) { priced[i] = price_now(stale[i]); });
  for (size_t i = 0; i < stale.size(); ++i) {
    note(stale[i], priced[i]);
    priority_[stale[i]] = static_cast<float>(priced[i].priority);
    flags_[stale[i]] &= ~kFlagStale;
  }
}

} // namespace vrs
