// The driver: read -> classify + evaluate -> queue -> pop -> plan -> commit -> re-evaluate the
// ring -> ... -> compact. Decisions live in the modules it calls; this file only sequences them.
#include <cmath>
#include <limits>

#include "bucket_queue.h"
#include "constraints.h"
#include "evaluation.h"
#include "heap_queue.h"
#include "input_check.h"
#include "local_error.h"
#include "orientation.h"
#include "removal.h"
#include "spatial_order.h"
#include "topology.h"
#include "vrs/simplify.h"
#include "workers.h"

namespace vrs {

namespace {

constexpr uint8_t kFlagLocked = 1;  // never removed: user lock, or next to a NaN/inf position
constexpr uint8_t kFlagRemoved = 2; // gone from the mesh
constexpr uint8_t kFlagStale = 32;  // queued with a price from before its ring last changed
constexpr uint8_t kFlagTaken = 64;  // in or next to a vertex removed in the current batch
// Removals planned together, read off the front of the queue. A constant, not the thread
// count: the output must not depend on it.
constexpr size_t kBatch = 128;
// Bits 2-4: the vertex's last plan's Reject (RejectCount: none), for Report::stop_detail.
constexpr int kRefusedShift = 2;
constexpr uint8_t kRefusedMask = 7 << kRefusedShift;
static_assert(RejectCount <= 7, "a Reject must fit the flag bits");

// Drops faces with a repeated corner: they have no area and no place in a manifold fan.
// `source[f]` becomes the input index of kept face f.
size_t drop_repeated_corner_faces(std::vector<uint32_t>& tris, std::vector<uint32_t>& source) {
  size_t out = 0;
  source.clear();
  source.reserve(tris.size() / 3);
  for (size_t i = 0; i < tris.size(); i += 3) {
    uint32_t a = tris[i], b = tris[i + 1], c = tris[i + 2];
    if (a == b || b == c || c == a) continue;
    source.push_back(static_cast<uint32_t>(i / 3));
    tris[out++] = a;
    tris[out++] = b;
    tris[out++] = c;
  }
  size_t dropped = (tris.size() - out) / 3;
  tris.resize(out);
  return dropped;
}

class Simplifier {
 public:
  Simplifier(Mesh& mesh, const Options& opt, Report& rep)
      : mesh_(mesh), opt_(opt), rep_(rep),
        eval_(opt.mode,
              opt.mode == Mode::Planar2D ? mesh_plane_normal(mesh.positions.data(), mesh.triangles)
                                         : Vec3{0, 0, 1},
              mesh.positions.data()) {
    limits_.min_normal_cos = std::cos(opt.max_normal_angle_deg * 3.14159265358979323846 / 180);
  }
  Simplifier(const Simplifier&) = delete;

  void prepare();
  template <class Queue> void run(Queue& queue);
  void compact();
  // Why the remaining vertices stay, when the target was not met (Report::stop_detail).
  std::string explain_stop() const;

 private:
  // A vertex of a single triangle goes with it only in the last-resort pass: that cuts a
  // triangle off the outline.
  bool removable(VertexKind k) const {
    return k == VertexKind::Interior ||
           (opt_.simplify_boundary &&
            (k == VertexKind::Boundary || (k == VertexKind::Corner && last_resort_)));
  }
  // What the constrained edges allow for a removable vertex: no constraint, a seam through it
  // (its ring positions in `seam`), or nothing (kept).
  enum class Along : uint8_t { Free, Seam, Kept };
  Along along(uint32_t v, const Ring& ring, std::array<int, 2>& seam) const;
  // The evaluation of v's plane and factor; along a seam the factor also counts v's distance
  // to the chord that replaces it (also put in `chord`, else 0). +inf factor when v must stay.
  Evaluation evaluate_plane(uint32_t v, const Ring& ring, double* chord = nullptr) const;
  // Priority of v with its current ring (the paper's factor or the planned patch's local
  // error), or +inf when v must stay. Reads only (the workers call it); the planned removal's
  // refusal, if a plan was made, goes to `why` (RejectCount: accepted or not planned) and is
  // recorded by note().
  struct Priced {
    double priority;
    Reject why = RejectCount;
    bool planned = false;
  };
  Priced evaluate(uint32_t v, const Ring& ring) const;
  void note(uint32_t v, const Priced& p);
  // Plans v's removal on its evaluated plane, then on a fallback direction; RejectCount = ok,
  // with the chosen patch's local error in `cost`.
  Reject plan(uint32_t v, const Ring& ring, const Evaluation& e, Patch& patch, double& cost,
              bool check_topology = true, bool price = true) const;
  static double price(const void* self, uint32_t v, const Ring& ring, const Patch& patch);
  static double estimate(const void* self, uint32_t v, const Ring& ring, const Patch& patch);
  bool target_met() const;
  float progress_fraction(size_t queued, size_t queued0) const;
  // A removal is committed in two steps: account() on the caller's thread, in queue order
  // (counts, seams, the neighbours' prices: marked stale or put on `reprice_`), then
  // rewrite() of the faces and their lists, on the workers: the removals of a batch touch
  // disjoint vertices.
  template <class Queue> void account(uint32_t v, const Ring& ring, const Patch& patch, Queue& q);
  struct Planned;
  void rewrite(Planned& p);
  // How v's removal changes the area of the faces around each ring vertex i: its faces i - 1
  // and i are replaced by the patch's triangles at i.
  void fan_area_changes(uint32_t v, const Ring& ring, const Patch& patch,
                        std::array<double, kMaxRing + 1>& change) const;
  // Prices the vertices on `reprice_` (on the workers) and queues them again.
  template <class Queue> void reprice(Queue& queue);
  // One removal read off the queue's front and planned (on the workers).
  struct Planned {
    std::array<std::pair<uint32_t, uint32_t>, 3 * kMaxRing> overflow; // (vertex, face) to add
    int overflows = 0;
    uint32_t v;
    int from; // the interval it was read off
    bool stale, usable;
    Reject why;
    double priority;
    Ring ring;
    Patch patch;
  };
  // Reads up to kBatch vertices off the front of the lowest interval into batch_.
  template <class Queue> size_t take_batch(Queue& queue);
  // Whether p's plan still holds: no removal of this batch was in or next to p's vertex or
  // its ring (their closed neighbourhoods are marked kFlagTaken by mark_taken).
  bool still_valid(const Planned& p) const;
  void mark_taken(uint32_t v, const Ring& ring);
  void plan_batch(size_t count);
  // The last resort when a count target is not met and nothing is left to remove: lifts the
  // input-normal veto and the outline-corner rule (with boundary simplification on) and
  // queues every removable vertex again. False if it was done already.
  template <class Queue> bool relax(Queue& queue);

  Mesh& mesh_;
  const Options& opt_;
  Report& rep_;
  Evaluator eval_;
  RemovalLimits limits_;
  bool last_resort_ = false; // see relax()
  // Queued neighbours of a removal are re-priced when popped. The paper's factor is the plane
  // alone, cheap to make at once: lazy only pays where the price is a plan.
  const bool lazy_ = opt_.lazy_reevaluation && opt_.priority == Priority::LocalError;
  Topology topo_;
  Workers workers_{opt_.threads > 0 ? opt_.threads : hardware_threads()};
  std::vector<Planned> batch_;
  std::vector<uint32_t> reprice_;
  std::vector<uint32_t> taken_;     // vertices marked kFlagTaken in this batch
  std::vector<uint32_t> committed_; // batch_ entries accounted, to rewrite
  std::vector<Priced> repriced_;
  Planner planner_{eval_, topo_, mesh_.triangles.data(), nullptr, limits_, {}, false};
  std::vector<float> factor_;
  std::vector<float> fan_area_; // area of each vertex's faces (kept up to date with lazy_)
  std::vector<float> normals_;  // unit vertex normals of the input surface, 3 a vertex
  std::vector<uint8_t> flags_;
  void set_refused(uint32_t v, Reject why) {
    flags_[v] = uint8_t((flags_[v] & ~kRefusedMask) | (why << kRefusedShift));
  }
  Reject refused(uint32_t v) const { return Reject((flags_[v] & kRefusedMask) >> kRefusedShift); }
  std::vector<uint32_t> face_source_;   // per face slot: its input face, or kRemoved once rewritten
  std::vector<uint32_t> corner_source_; // per face slot corner: the input corner it carries
  std::vector<float> face_bound_;       // per face slot: its certified error bound (max_error)
  Constraints constraints_;
  SpatialOrder order_;
  size_t faces_ = 0, vertices_ = 0, target_faces_ = 0, target_vertices_ = 0;
  size_t faces0_ = 0;
  double reference_area_ = 1; // mean input triangle area (LocalError's weight)
};

void Simplifier::prepare() {
  const size_t n = mesh_.vertex_count();
  rep_.dropped_degenerate_faces = drop_repeated_corner_faces(mesh_.triangles, face_source_);
  // Inside, vertices and faces go in spatial order (compact() restores the input's).
  order_ = spatial_order(mesh_.positions, mesh_.triangles);
  {
    std::vector<uint32_t> source(face_source_.size());
    for (size_t f = 0; f < source.size(); ++f)
      source[f] = face_source_[order_.face_old[f]];
    face_source_.swap(source);
  }
  flags_.assign(n, 0);
  for (uint32_t v = 0; v < n; ++v)
    set_refused(v, RejectCount);
  if (opt_.locked)
    for (size_t v = 0; v < n; ++v)
      if ((*opt_.locked)[order_.vertex_old[v]]) flags_[v] |= kFlagLocked;
  // A NaN/inf position poisons every plane it takes part in: lock it and its neighbours.
  const auto& t = mesh_.triangles;
  for (size_t v = 0; v < n; ++v)
    if (!is_finite(eval_.position(static_cast<uint32_t>(v)))) ++rep_.nonfinite_vertices;
  if (rep_.nonfinite_vertices)
    for (size_t i = 0; i < t.size(); i += 3)
      if (!is_finite(eval_.position(t[i])) || !is_finite(eval_.position(t[i + 1])) ||
          !is_finite(eval_.position(t[i + 2])))
        flags_[t[i]] |= kFlagLocked, flags_[t[i + 1]] |= kFlagLocked,
            flags_[t[i + 2]] |= kFlagLocked;

  topo_.build(t, n);
  // Before anything reads a fan: faces written in random orientation make every vertex look
  // non-manifold.
  std::vector<uint8_t> reversed;
  rep_.reoriented_faces = orient_coherently(mesh_.triangles, topo_, face_source_.data(), reversed);
  {
    Options renumbered = opt_;
    std::vector<uint32_t> pairs;
    if (opt_.constrained_edges) {
      pairs = *opt_.constrained_edges;
      for (uint32_t& v : pairs)
        if (v < n) v = order_.vertex_new[v]; // out-of-range pairs stay ignored
      renumbered.constrained_edges = &pairs;
    }
    rep_.constrained_edges = constraints_.build(renumbered, mesh_.positions.data(), t, topo_, n);
  }
  if (opt_.corner_sources) {
    corner_source_.resize(t.size());
    for (size_t f = 0; f < face_source_.size(); ++f)
      for (int c = 0; c < 3; ++c)
        corner_source_[3 * f + c] =
            3 * face_source_[f] + (reversed.empty() || !reversed[f] || !c ? c : 3 - c);
  }
  normals_ = vertex_normals(mesh_.positions, t);
  reference_area_ = mean_triangle_area(mesh_.positions.data(), t);
  if (lazy_) {
    fan_area_.assign(n, 0.0f);
    for (size_t i = 0; i < t.size(); i += 3) {
      const float a = static_cast<float>(
          triangle_area(eval_.position(t[i]), eval_.position(t[i + 1]), eval_.position(t[i + 2])));
      for (int c = 0; c < 3; ++c)
        fan_area_[t[i + c]] += a;
    }
  }
  planner_ =
      Planner(eval_, topo_, t.data(), normals_.data(), limits_, Pricer{&estimate, &price, this},
              opt_.fill == Fill::Best, opt_.mode != Mode::Surface3D);
  if (opt_.max_error > 0) {
    face_bound_.assign(t.size() / 3, 0.0f); // the input is its own surface
    limits_.max_error = opt_.max_error;
    planner_.set_face_bounds(face_bound_.data());
  }
  factor_.assign(n, std::numeric_limits<float>::infinity());
  faces_ = faces0_ = t.size() / 3;
  // Every vertex's kind and first price, on the workers (reads only; each writes its own
  // slots), then the counts in vertex order.
  constexpr uint8_t kKeptOnConstraints = 128; // beside the VertexKind
  std::vector<uint8_t> kinds(n);
  std::vector<Priced> first(n);
  workers_.for_each(
      n,
      [&](size_t i) {
        const uint32_t v = static_cast<uint32_t>(i);
        Ring ring;
        VertexKind kind = topo_.ring(v, t.data(), opt_.max_valence, ring);
        kinds[v] = static_cast<uint8_t>(kind);
        if (kind == VertexKind::Isolated || flags_[v] & kFlagLocked || !removable(kind)) return;
        std::array<int, 2> seam;
        if (along(v, ring, seam) == Along::Kept)
          kinds[v] |= kKeptOnConstraints;
        else
          first[v] = evaluate(v, ring);
      },
      256);
  for (uint32_t v = 0; v < n; ++v) {
    const VertexKind kind = static_cast<VertexKind>(kinds[v] & ~kKeptOnConstraints);
    switch (kind) {
    case VertexKind::Isolated: ++rep_.unreferenced_vertices; continue;
    case VertexKind::Boundary:
    case VertexKind::Corner: rep_.kept_boundary += !removable(kind); break;
    case VertexKind::NonManifold: ++rep_.kept_nonmanifold; break;
    case VertexKind::HighValence: ++rep_.kept_high_valence; break;
    case VertexKind::Interior: break;
    }
    ++vertices_;
    if (flags_[v] & kFlagLocked) {
      ++rep_.kept_locked;
      continue;
    }
    if (!removable(kind)) continue;
    if (kinds[v] & kKeptOnConstraints) {
      ++rep_.kept_constrained;
      continue;
    }
    note(v, first[v]);
    factor_[v] = static_cast<float>(first[v].priority);
  }

  const TargetKind tk = opt_.target.kind;
  target_faces_ = tk == TargetKind::Faces ? opt_.target.faces
                  : tk == TargetKind::Ratio
                      ? static_cast<size_t>(std::llround(opt_.target.ratio * faces0_))
                      : 0;
  target_vertices_ = tk == TargetKind::Vertices ? opt_.target.vertices : 0;
}

Simplifier::Along Simplifier::along(uint32_t v, const Ring& ring, std::array<int, 2>& seam) const {
  const int degree = constraints_.degree(v);
  if (degree == 0) return Along::Free;
  return constraints_.seam_of(v, ring, seam[0], seam[1]) ? Along::Seam : Along::Kept;
}

Evaluation Simplifier::evaluate_plane(uint32_t v, const Ring& ring, double* chord) const {
  Evaluation e = eval_.evaluate(v, ring, opt_.simplify_boundary);
  std::array<int, 2> seam;
  double to_chord = 0;
  switch (along(v, ring, seam)) {
  case Along::Free: break;
  case Along::Kept: e.factor = std::numeric_limits<double>::infinity(); break;
  case Along::Seam: // the polyline's own deviation, which a flat neighbourhood does not show
    to_chord = distance_to_line(eval_.position(v), eval_.position(ring.v[seam[0]]),
                                eval_.position(ring.v[seam[1]]));
    e.factor = std::max(e.factor, to_chord);
    break;
  }
  if (chord) *chord = to_chord;
  return e;
}

Simplifier::Priced Simplifier::evaluate(uint32_t v, const Ring& ring) const {
  double chord = 0;
  Evaluation e = evaluate_plane(v, ring, &chord);
  if (opt_.priority == Priority::Factor || !std::isfinite(e.factor)) return {e.factor};
  Patch patch;
  double cost = 0;
  // The mesh look-ups wait for the pop, where the plan is made again in full.
  Reject why = plan(v, ring, e, patch, cost, /*check_topology=*/false);
  if (why != RejectCount) // not queued; evaluated again when its ring changes
    return {std::numeric_limits<double>::infinity(), why, true};
  return {std::max(cost, chord), RejectCount, true};
}

void Simplifier::note(uint32_t v, const Priced& p) {
  if (!p.planned) return;
  set_refused(v, p.why);
  if (p.why != RejectCount) ++rep_.rejected[p.why];
}

double Simplifier::price(const void* self, uint32_t v, const Ring& ring, const Patch& patch) {
  const auto* s = static_cast<const Simplifier*>(self);
  const double local = patch_error(v, ring, patch, s->eval_, s->reference_area_);
  if (s->face_bound_.empty()) return local;
  // With a bound, what will stop the run is the bound: the removals that raise it least go
  // first (1-4 % fewer faces at the same bound on elephant, fandisk, armadillo).
  double worst = 0;
  for (int t = 0; t < patch.count; ++t)
    worst = std::max(worst, double(patch.bound[t]));
  return std::max(local, worst);
}

double Simplifier::estimate(const void* self, uint32_t v, const Ring&, const Patch& patch) {
  return drop_height(v, patch, static_cast<const Simplifier*>(self)->eval_);
}

Reject Simplifier::plan(uint32_t v, const Ring& ring, const Evaluation& e, Patch& patch,
                        double& cost, bool check_topology, bool price) const {
  std::array<int, 2> seam;
  const bool on_seam = along(v, ring, seam) == Along::Seam;
  auto attempt = [&](Vec3 d) {
    return on_seam
               ? planner_.plan_seam(v, ring, seam[0], seam[1], d, patch, cost, check_topology,
                                    price)
               : planner_.plan(v, ring, d, patch, cost, check_topology, OpenRing::Border, price);
  };
  Reject why = attempt(e.normal);
  // At tips, creases and thin parts the average plane of a strongly curved ring can fold it
  // or tilt the patch away, while another direction still sees the ring as a star.
  if ((why == RejectFold || why == RejectFlip) && opt_.mode == Mode::Surface3D) {
    Vec3 d;
    if (star_direction(v, ring, eval_, d)) why = attempt(d);
  }
  return why;
}

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

void Simplifier::fan_area_changes(uint32_t v, const Ring& ring, const Patch& patch,
                                  std::array<double, kMaxRing + 1>& change) const {
  const int k = ring.verts;
  const Vec3 c = eval_.position(v);
  const auto& q = patch.q;                         // the ring's positions
  std::array<double, kMaxRing> old_area, new_area; // each face's area, made once
  for (int f = 0; f < ring.faces; ++f)
    old_area[f] = triangle_area(c, q[f], q[(f + 1) % k]);
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

void Simplifier::rewrite(Planned& p) {
  const uint32_t v = p.v;
  const Ring& ring = p.ring;
  const Patch& patch = p.patch;
  uint32_t* tris = mesh_.triangles.data();
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
    face_source_[f] = kRemoved;
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
}

template <class Queue>
void Simplifier::account(uint32_t v, const Ring& ring, const Patch& patch, Queue& queue) {
  std::array<int, 2> seam;
  if (along(v, ring, seam) == Along::Seam) constraints_.merge(v, ring.v[seam[0]], ring.v[seam[1]]);
  flags_[v] |= kFlagRemoved;
  faces_ -= static_cast<size_t>(ring.faces - patch.count);
  --vertices_;
  ++rep_.removed;
  rep_.relaxed_removals += last_resort_;
  rep_.max_removed_factor = std::max(rep_.max_removed_factor, double(factor_[v]));

  // The neighbours' planes and rings changed. Queued ones are priced again when popped (lazy);
  // the others (refused, or kept until now) are evaluated now and appended to the back of
  // their interval, as every neighbour is with eager re-evaluation.
  std::array<double, kMaxRing + 1> area_change;
  if (lazy_) fan_area_changes(v, ring, patch, area_change);
  for (int i = 0; i < ring.verts; ++i) {
    const uint32_t u = ring.v[i];
    const float before = lazy_ ? fan_area_[u] : 0.0f;
    if (lazy_) fan_area_[u] = static_cast<float>(before + area_change[i]);
    if (flags_[u] & kFlagLocked) continue;
    if (lazy_ && queue.contains(u)) {
      // Stale: priced again when popped. Meanwhile its place follows the part of its price
      // known without a plan: the local error weighs distances by sqrt(fan area), and the
      // fan's area just changed (the distances are taken as they were). Left in place, a
      // neighbour whose price fell waits behind where it belongs.
      flags_[u] |= kFlagStale;
      if (before > 0 && fan_area_[u] > 0) {
        factor_[u] = static_cast<float>(factor_[u] * std::sqrt(fan_area_[u] / before));
        queue.update(u, factor_[u]);
      }
    } else {
      reprice_.push_back(u);
    }
  }
}

template <class Queue> void Simplifier::reprice(Queue& queue) {
  // A vertex is next to at most one removal of a batch, so the list has no repeats, and each
  // price reads only the vertex's own ring.
  repriced_.resize(reprice_.size());
  const uint32_t* tris = mesh_.triangles.data();
  workers_.for_each(reprice_.size(), [&](size_t i) {
    const uint32_t u = reprice_[i];
    Ring r;
    VertexKind kind = topo_.ring(u, tris, opt_.max_valence, r);
    repriced_[i] =
        removable(kind) ? evaluate(u, r) : Priced{std::numeric_limits<double>::infinity()};
  });
  const bool by_factor = opt_.target.kind == TargetKind::MaxFactor;
  for (size_t i = 0; i < reprice_.size(); ++i) {
    const uint32_t u = reprice_[i];
    const double f = repriced_[i].priority;
    note(u, repriced_[i]);
    factor_[u] = static_cast<float>(f);
    flags_[u] &= ~kFlagStale;
    if (std::isfinite(f) && (!by_factor || f <= opt_.target.max_factor))
      queue.push(u, f);
    else
      queue.erase(u);
  }
  reprice_.clear();
}

template <class Queue> size_t Simplifier::take_batch(Queue& queue) {
  if (batch_.size() < kBatch) batch_.resize(kBatch);
  size_t count = 0;
  // From the lowest interval only: reaching 16 intervals up filled the batches but cost 2 % of
  // mean and 8 % of max error on the whole data set.
  for (uint32_t v = queue.front(); v != kNone && count < kBatch; v = queue.after(v)) {
    batch_[count].v = v;
    batch_[count++].from = queue.interval(v);
  }
  return count;
}

bool Simplifier::still_valid(const Planned& p) const {
  if (flags_[p.v] & kFlagTaken) return false;
  for (int i = 0; i < p.ring.verts; ++i)
    if (flags_[p.ring.v[i]] & kFlagTaken) return false;
  return true;
}

void Simplifier::mark_taken(uint32_t v, const Ring& ring) {
  for (int i = -1; i < ring.verts; ++i) {
    const uint32_t u = i < 0 ? v : ring.v[i];
    if (!(flags_[u] & kFlagTaken)) flags_[u] |= kFlagTaken, taken_.push_back(u);
  }
}

void Simplifier::plan_batch(size_t count) {
  const bool local = opt_.priority == Priority::LocalError;
  workers_.for_each(count, [&](size_t b) {
    Planned& p = batch_[b];
    p.stale = flags_[p.v] & kFlagStale;
    p.why = RejectCount;
    p.usable = removable(topo_.ring(p.v, mesh_.triangles.data(), opt_.max_valence, p.ring));
    if (!p.usable) return;
    double chord = 0, cost = 0;
    Evaluation e = evaluate_plane(p.v, p.ring, &chord);
    if (!std::isfinite(e.factor)) {
      p.usable = false;
      return;
    }
    // The plan is made again: a diagonal may have become an edge since v was queued. Only a
    // stale price is made again.
    p.why = plan(p.v, p.ring, e, p.patch, cost, /*check_topology=*/true, p.stale && local);
    p.priority = local ? std::max(cost, chord) : e.factor;
  });
}

template <class Queue> void Simplifier::run(Queue& queue) {
  const size_t n = mesh_.vertex_count();
  IntervalMap map;
  map.n = opt_.intervals;
  map.kind = opt_.mapping;
  for (size_t v = 0; v < n; ++v)
    if (std::isfinite(factor_[v])) map.f_max = std::max(map.f_max, double(factor_[v]));
  queue.init(n, map);
  const bool by_factor = opt_.target.kind == TargetKind::MaxFactor;
  // In the input's order, as the paper fills its table: the FIFO of an interval then follows
  // the input, not space, and removals spread over the mesh.
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t v = order_.vertex_new[i];
    if (std::isfinite(factor_[v]) && (!by_factor || factor_[v] <= opt_.target.max_factor))
      queue.push(v, factor_[v]);
  }

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
    if (queue.empty() && counts && relax(queue)) continue;
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
        queue.respread(factor_.data());
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
    const size_t count = take_batch(queue);
    plan_batch(count);
    since_progress = since_progress >= 256 ? count : since_progress + count;
    for (size_t b = 0; b < count && !target_met(); ++b) {
      Planned& p = batch_[b];
      const uint32_t v = p.v;
      if (!still_valid(p)) continue;
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
        factor_[v] = static_cast<float>(p.priority);
        if (by_factor && !(p.priority <= opt_.target.max_factor)) continue;
        if (!queue.leads(p.priority, p.from)) {
          queue.push(v, p.priority);
          continue;
        }
      }
      mark_taken(v, p.ring);
      account(v, p.ring, p.patch, queue);
      committed_.push_back(uint32_t(b));
    }
    for (uint32_t u : taken_)
      flags_[u] &= ~kFlagTaken;
    taken_.clear();
    workers_.for_each(committed_.size(), [&](size_t i) { rewrite(batch_[committed_[i]]); });
    for (uint32_t b : committed_)
      for (int i = 0; i < batch_[b].overflows; ++i)
        topo_.add_face(batch_[b].overflow[i].first, batch_[b].overflow[i].second);
    committed_.clear();
    reprice(queue);
  }
  if (opt_.progress && rep_.stop != StopReason::Cancelled) opt_.progress(1.0f);
}

template <class Queue> bool Simplifier::relax(Queue& queue) {
  if (last_resort_) return false;
  // Nothing to gain when the kept border alone needs more than the target: on the input's
  // surface (Euler, manifold), any triangulation keeping its B border vertices has at least
  // 2B - 2V + F faces. Lifting vetoes there would only crumple the interior.
  if (!opt_.simplify_boundary && rep_.kept_boundary) {
    const long b = long(rep_.kept_boundary), v = long(vertices_ + rep_.removed), f = long(faces0_);
    if ((target_faces_ && 2 * b - 2 * v + f > long(target_faces_)) ||
        (target_vertices_ && b > long(target_vertices_)))
      return false;
  }
  // What the last resort lifts, in one place: the input normals asked of one corner of a new
  // triangle only, the outline corners (the evaluation's setting) and, through removable(),
  // the single triangles; and where every filling is refused, the least-cost one is tried.
  // The fold-over veto stays: where only folding fillings are left, the run stops and says
  // so. (In two steps, input normals at two corners first, it measured worse: cow at 1 %,
  // mean 0.0193 against 0.0149 of the diagonal; ChineseDragon-10kv stalled above its target.)
  last_resort_ = true;
  limits_.agreeing_corners = 1;
  limits_.least_cost_filling = true;
  eval_.set_boundary_corner_cos(-1.0);
  Ring ring;
  const uint32_t* tris = mesh_.triangles.data();
  for (uint32_t i = 0; i < mesh_.vertex_count(); ++i) {
    const uint32_t v = order_.vertex_new[i]; // input order, as run() queues
    if (flags_[v] & (kFlagLocked | kFlagRemoved) || topo_.valence(v) == 0) continue;
    if (!removable(topo_.ring(v, tris, opt_.max_valence, ring))) continue;
    const Priced p = evaluate(v, ring);
    note(v, p);
    factor_[v] = static_cast<float>(p.priority);
    flags_[v] &= ~kFlagStale;
    if (std::isfinite(p.priority)) queue.push(v, p.priority);
  }
  return !queue.empty();
}

std::string Simplifier::explain_stop() const {
  size_t boundary = 0, constrained = 0, locked = 0, nonmanifold = 0, high = 0, untried = 0;
  size_t corners = 0;
  size_t refused_by[RejectCount] = {};
  Ring ring;
  std::array<int, 2> seam;
  for (uint32_t v = 0; v < mesh_.vertex_count(); ++v) {
    if (flags_[v] & kFlagRemoved || topo_.valence(v) == 0) continue;
    VertexKind kind = topo_.ring(v, mesh_.triangles.data(), opt_.max_valence, ring);
    if (flags_[v] & kFlagLocked)
      ++locked;
    else if (kind == VertexKind::NonManifold)
      ++nonmanifold;
    else if (kind == VertexKind::HighValence)
      ++high;
    else if (!removable(kind))
      ++boundary;
    else if (along(v, ring, seam) == Along::Kept)
      ++constrained;
    else if (refused(v) != RejectCount)
      ++refused_by[refused(v)];
    else if (kind == VertexKind::Boundary)
      ++corners;
    else
      ++untried;
  }
  std::string out;
  auto add = [&](size_t count, const std::string& what) {
    if (!count) return;
    out += (out.empty() ? "" : "; ") + std::to_string(count) + " " + what;
  };
  add(boundary, opt_.simplify_boundary ? "on the boundary in a single triangle"
                                       : "on the boundary, kept (boundary simplification is off)");
  add(corners, "at corners of the outline");
  add(constrained, "on seams or creases where they end, meet or cross");
  add(locked, "locked");
  add(nonmanifold, "non-manifold or inconsistently oriented");
  add(high, "of too high valence");
  std::string vetoes;
  for (int r = 0; r < RejectCount; ++r)
    if (refused_by[r])
      vetoes += (vetoes.empty() ? "" : ", ") + std::string(reject_name(Reject(r))) + " " +
                std::to_string(refused_by[r]);
  size_t total_refused = 0;
  for (size_t r : refused_by)
    total_refused += r;
  add(total_refused, "refused by the vetoes (" + vetoes + ")");
  if (last_resort_ && refused_by[RejectFoldOver])
    out += "; the last resort stopped: every filling left for " +
           std::to_string(refused_by[RejectFoldOver]) +
           " of them would fold the surface over the faces it replaces";
  add(untried, "without a usable plane (degenerate or non-finite neighbourhood)");
  return "remaining vertices: " + (out.empty() ? std::string("none") : out);
}

void Simplifier::compact() {
  // Back to the input's order: vertices by input index, faces by the input slot they took.
  const size_t n = mesh_.vertex_count();
  auto& pos = mesh_.positions;
  rep_.remap.assign(n, kRemoved);
  std::vector<uint32_t> out_index(n, kRemoved); // internal vertex -> output index
  std::vector<float> kept;
  kept.reserve(pos.size());
  uint32_t next = 0;
  for (size_t i = 0; i < n; ++i) {
    const uint32_t v = order_.vertex_new[i];
    if (flags_[v] & kFlagRemoved) continue;
    kept.insert(kept.end(), &pos[3 * size_t(v)], &pos[3 * size_t(v)] + 3);
    rep_.remap[i] = out_index[v] = next++;
  }
  pos.swap(kept);
  std::vector<float>().swap(kept);

  auto& tris = mesh_.triangles;
  const size_t slots = tris.size() / 3;
  std::vector<uint32_t> slot_of(slots); // input slot -> internal slot
  for (size_t f = 0; f < slots; ++f)
    slot_of[order_.face_old[f]] = uint32_t(f);
  std::vector<uint32_t> out;
  out.reserve(tris.size());
  rep_.face_source.clear();
  rep_.corner_source.clear();
  for (size_t j = 0; j < slots; ++j) {
    const size_t f = slot_of[j];
    if (tris[3 * f] == kNone) continue;
    rep_.face_source.push_back(face_source_[f]);
    if (!face_bound_.empty()) rep_.error_bound = std::max(rep_.error_bound, double(face_bound_[f]));
    if (!corner_source_.empty())
      rep_.corner_source.insert(rep_.corner_source.end(), &corner_source_[3 * f],
                                &corner_source_[3 * f] + 3);
    for (int c = 0; c < 3; ++c)
      out.push_back(out_index[tris[3 * f + c]]);
  }
  tris.swap(out);
  rep_.faces = tris.size() / 3;
  rep_.vertices = next;
}

std::string input_warnings(const Report& r) {
  std::string w;
  auto add = [&](size_t count, const char* what) {
    if (!count) return;
    if (!w.empty()) w += "; ";
    w += std::to_string(count) + " " + what;
  };
  add(r.dropped_degenerate_faces, "faces with a repeated vertex dropped");
  add(r.reoriented_faces, "faces reversed to agree with their neighbours' orientation");
  add(r.nonfinite_vertices, "vertices with NaN/inf coordinates kept with their neighbours");
  add(r.kept_nonmanifold, "non-manifold vertices kept");
  add(r.kept_high_valence, "vertices of too high valence kept");
  add(r.unreferenced_vertices, "unreferenced vertices left untouched");
  return w;
}

} // namespace

Report simplify(Mesh& mesh, const Options& options) {
  Report rep;
  rep.input_vertices = mesh.vertex_count();
  rep.input_faces = mesh.face_count();
  rep.vertices = rep.input_vertices;
  rep.faces = rep.input_faces;
  std::string error = check_mesh(mesh);
  if (error.empty()) error = check_options(options, mesh.vertex_count());
  if (!error.empty()) {
    rep.message = error;
    return rep;
  }

  Simplifier s(mesh, options, rep);
  s.prepare();
  if (options.queue == QueueKind::Heap) {
    HeapQueue q;
    s.run(q);
  } else {
    BucketQueue q;
    s.run(q);
  }
  if (rep.stop == StopReason::NoCandidates || rep.stop == StopReason::ErrorBound)
    rep.stop_detail = s.explain_stop();
  s.compact();
  rep.ok = true;
  rep.target_reached = rep.stop == StopReason::TargetReached || rep.stop == StopReason::MaxFactor ||
                       rep.stop == StopReason::LastInterval || rep.stop == StopReason::ErrorBound;
  rep.message = input_warnings(rep);
  return rep;
}

} // namespace vrs
