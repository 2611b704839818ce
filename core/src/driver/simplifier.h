// The driver's state and its steps. The steps live in their own files, in the order data flows:
// setup.cpp (read, classify, first prices) -> pricing.cpp (a vertex's plan and price) ->
// scheduler.cpp (batches read off the queue, planned on the workers, checked) ->
// commit.cpp (faces rewritten) -> accounting.cpp (counts, neighbours re-priced) ->
// last_resort.cpp -> stop_explanation.cpp / output.cpp; simplifier.cpp sequences them.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "base/workers.h"
#include "driver/parts.h"
#include "driver/scheduler.h"
#include "driver/slide.h"
#include "driver/stop_explanation.h"
#include "driver/vertex_flags.h"
#include "evaluate/carried_points.h"
#include "evaluate/evaluation.h"
#include "mesh/constraints.h"
#include "mesh/fan_split.h"
#include "mesh/spatial_order.h"
#include "mesh/split_vertices.h"
#include "mesh/topology.h"
#include "remove/removal.h"
#include "vrs/simplify.h"

namespace vrs {

struct LocalInput; // local_input.h

class Simplifier {
 public:
  Simplifier(Mesh& mesh, const Options& opt, Report& rep)
      : mesh_(mesh), opt_(opt), rep_(rep),
        eval_(opt.mode,
              opt.mode == Mode::Planar2D ? mesh_plane_normal(mesh.positions.data(), mesh.triangles)
                                         : Vec3{0, 0, 1},
              mesh.positions.data()) {
    limits_.min_normal_cos = std::cos(opt.max_normal_angle_deg * 3.14159265358979323846 / 180);
    // The local error prices an outline corner's removal (its distance to the new patch, over
    // the fan's area): the corner rule is the factor's. Kept, it left small open pieces (hair
    // strips, a shark's holes) dense until the last resort, while the rest paid for them.
    if (opt.tuning.priority != Priority::Factor) eval_.set_boundary_corner_cos(-1.0);
  }
  Simplifier(const Simplifier&) = delete;

  void prepare(); // setup.cpp
  // Options::simplify_boundary_when_needed: whether the kept border would take more than a
  // quarter of the count target (setup.cpp).
  bool border_needs_simplifying();
  // Whether keeping `border` vertices of a surface of `used` vertices and the input's faces
  // would take more than `share` of the count target (at least 2B - 2V + F faces, Euler).
  bool border_takes(size_t border, size_t used, double share) const;
  // Then the border vertices at another border vertex's exact position (a seam of split
  // vertices) stay: kFlagTwin.
  void lock_split_seams();
  // Simplification by parts (parts.h), when the mesh is large enough: the first removals, on
  // the parts' own queues; false when cancelled.
  bool run_parts(); // parts.cpp
  // progressive.cpp: record each removal into `log` (one thread: the order is the writes');
  // after the run, the faces standing: their slots and corners (the base of the record).
  void record_removals(std::vector<uint32_t>* log) { removal_log_ = log; }
  void standing_faces(std::vector<uint32_t>& slots, std::vector<uint32_t>& corners) const;
  template <class Queue> void run(Queue& queue); // simplifier.cpp
  void compact();                                // compact.cpp
  // After the run: kept vertices give their place to removed ones nearer the input.
  void slide(); // slide.cpp
  double parallel_seconds() const { return workers_.parallel_seconds(); }
  double span_seconds(int threads) const { return workers_.span_seconds(threads); }
  // Why the remaining vertices stay, when the target was not met: Report::stop_detail and
  // stop_cause (stop_explanation.cpp).
  void explain_stop();

 private:
  Remaining count_remaining() const;
  bool next_to_nonfinite(uint32_t v, const Ring& ring) const; // stop_explanation.cpp
  // The slide's steps (slide.cpp): the fans to try; the vertices they may ask about, each a
  // slot with its input faces' corners and a third of their area; a fan's choice, and writing
  // it.
  std::vector<uint32_t> slide_gate();
  void slide_index(const std::vector<uint32_t>& fans);
  uint32_t slide_choice(uint32_t v, const Ring& ring) const;
  void slide_commit(uint32_t v, uint32_t u, const Ring& ring);
  bool slide_local(uint32_t v, const Ring& ring, LocalInput& in) const;
  // Face slot f is, untouched, half of a polygon the caller keeps (Options::polygon_faces).
  bool polygon_face(uint32_t f) const;
  SlideState slide_;
  // A vertex of a single triangle goes with it only in the last-resort pass: that cuts a
  // triangle off the outline.
  bool removable(VertexKind k) const {
    return k == VertexKind::Interior ||
           (simplify_boundary_ &&
            (k == VertexKind::Boundary || (k == VertexKind::Corner && last_resort())));
  }
  bool target_met() const;
  float progress_fraction(size_t queued, size_t queued0) const;

  // --- pricing.cpp
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
  // evaluate() on v's ring as it is now; +inf when v is no longer removable.
  Priced price_now(uint32_t v) const;
  void note(uint32_t v, const Priced& p);
  // --- setup.cpp: the set-up from the fans on (normal cones to every vertex's kind and first
  // price); then, where several fans meet at a vertex, a copy a fan (true: set up again).
  // A first price, kept only for the vertices priced (their kinds say which): a plain record,
  // so that the arrays need no fill before the workers write them.
  struct FirstPrice {
    double priority;
    Reject why;
    bool planned;
  };
  void first_prices(UninitVector<uint8_t>& kinds, UninitVector<FirstPrice>& first);
  bool split_fans_apart(const UninitVector<uint8_t>& kinds);
  // Plans v's removal on its evaluated plane, then on a fallback direction; RejectCount = ok,
  // with the chosen patch's local error in `cost`.
  // `hinted`: v's ring is the one its last plan saw (a pop whose price is still today's), so
  // that plan's candidate (chosen_) is tried first.
  // `lead`: Planner::plan's (a plan priced above it is not asked the mesh's vetoes).
  Reject plan(uint32_t v, const Ring& ring, const Evaluation& e, Patch& patch, double& cost,
              bool check_topology = true, bool price = true, bool hinted = false,
              double lead = std::numeric_limits<double>::infinity()) const;
  static double price(const void* self, uint32_t v, const Ring& ring, const Patch& patch);
  static double estimate(const void* self, uint32_t v, const Ring& ring, const Patch& patch,
                         double cap, bool& complete);

  // --- scheduler.cpp
  // Plans p.v's removal against today's mesh (reads only: the workers call it). `areas`: the
  // fan area changes made too (Planned::area_change; else the caller makes them if it commits).
  void plan_removal(Planned& p, bool areas = true) const;
  // Plans batch_ids_[0, count) into batch_ on the workers against today's mesh.
  template <class Queue> void plan_batch(size_t count, const Queue& queue);

  // --- commit.cpp, accounting.cpp
  // A removal is committed in two steps: account() on the caller's thread, in queue order
  // (counts, seams, the neighbours' prices: marked stale or put on `reprice_`), then
  // rewrite() of the faces and their lists, on the workers: the removals of a batch touch
  // disjoint vertices.
  template <class Queue> void account(const Planned& p, Queue& q);
  // The removal's neighbours: queued ones marked stale, the others put on `reprice`; frozen
  // ones (parts.h; null: none) marked stale only.
  template <class Queue>
  void touch_ring(const Planned& p, Queue& q, std::vector<uint32_t>& reprice,
                  const uint8_t* frozen);
  void rewrite(Planned& p);
  // --- commit.cpp: the removals' record for a progressive mesh (progressive.h), in the order
  // they are written. Each: the fan's face count, the removed vertex's input corner, then per
  // fan face its slot (input face) and its three input corners, as the output orients them.
  std::vector<uint32_t>* removal_log_ = nullptr;
  void log_removal(const Planned& p);
  uint32_t slot_label(uint32_t f) const;
  void face_corners(uint32_t f, uint32_t out[3]) const;
  // Prices the vertices on `reprice_` (on the workers) and queues them again.
  template <class Queue> void reprice(Queue& queue);

  // --- parts.cpp
  struct Part;
  static constexpr int kPartRounds = 32;
  static constexpr double kPartsLeave = 0.15; // of the removals: the last ones for the whole queue
  bool by_parts() const;
  size_t removals_needed() const;
  // One cut's rounds (false: cancelled), then its frozen vertices priced again.
  bool run_cut(Parts& parts, size_t needed0);
  void price_frozen(const Parts& parts);
  // Removes the part's cheapest vertices up to `threshold`, at most `cap` of them.
  void run_part(Part& part, double threshold, size_t cap, const uint8_t* frozen);

  // --- last_resort.cpp
  // When a count target is not met and nothing is left to remove, or the next removal would
  // be a price jump: first lets one corner of a new triangle face away from the input's
  // normal; then, at the next exhaustion, the last resort lifts the input-normal veto to one
  // corner and the outline-corner rule (with boundary simplification on). Queues every
  // removable vertex again. False when nothing is left to relax.
  template <class Queue> bool relax(Queue& queue, bool after_jump);
  // Prices every removable vertex again and queues it (in input order, as run() does).
  template <class Queue> void requeue(Queue& queue);

  Mesh& mesh_;
  const Options& opt_;
  Report& rep_;
  Evaluator eval_;
  RemovalLimits limits_;
  // How far relax() has eased the vetoes: not yet, one corner of a new triangle may face away
  // from the input's normal, or the last resort (see relax()).
  enum class RelaxLevel : uint8_t { Strict, Eased, LastResort };
  RelaxLevel relax_level_ = RelaxLevel::Strict;
  bool eased() const { return relax_level_ != RelaxLevel::Strict; }
  bool last_resort() const { return relax_level_ == RelaxLevel::LastResort; }
  // Options::max_price_jump: the least price a jump is measured from (1e-3 of the diagonal),
  // and, once the run stopped at one, the price and the removal it was measured from.
  double jump_floor_ = 0, jump_price_ = 0, jump_from_ = 0;
  // The dearest removal made before the first relax(): relaxed removals are measured from it.
  // Measured from the dearest so far, a relaxed run climbed by small steps from one removal
  // to the next and ate a bolt's head into a cone.
  double relaxed_from_ = 0;
  double jump_base() const { return eased() ? relaxed_from_ : rep_.max_removed_factor; }
  // Once eased, half the jump: at the whole of it the eased passes' last removals flattened
  // steps and thin walls that no veto sees, for a few more faces kept; a smaller share stops
  // more runs short.
  static constexpr double kEasedJumpShare = 0.5;
  double jump_bar() const { return opt_.max_price_jump * (eased() ? kEasedJumpShare : 1.0); }
  // Whether removing v at `price` would be such a jump (with a count target).
  // Not before 16 removals (a few are no history to jump from), nor under an error bound (it
  // says itself how far a removal may go).
  bool jumps(double price) const {
    return opt_.max_price_jump > 0 && opt_.tuning.priority == Priority::LocalError &&
           rep_.removed >= 16 && !(opt_.max_error > 0 && std::isfinite(opt_.max_error)) &&
           price > jump_bar() * std::max(jump_base(), jump_floor_);
  }
  bool simplify_boundary_ = opt_.simplify_boundary; // or on when the kept border needs it
  // Queued neighbours of a removal are re-priced when popped. The paper's factor is the plane
  // alone, cheap to make at once: lazy only pays where the price is a plan, and on a large
  // mesh (Tuning::lazy_from_faces).
  const bool lazy_ = opt_.tuning.lazy_reevaluation &&
                     opt_.tuning.priority == Priority::LocalError &&
                     mesh_.face_count() >= opt_.tuning.lazy_from_faces;
  Topology topo_;
  Workers workers_{opt_.threads > 0 ? opt_.threads : usable_cores()};
  std::vector<Planned> batch_;
  std::vector<uint32_t> batch_ids_; // the vertices read off the queue for batch_
  int batch_from_ = 0;              // the interval they were read off
  TakenMarks taken_;
  std::vector<uint32_t> reprice_;
  std::vector<uint32_t> committed_; // batch_ entries accounted, to rewrite
  std::vector<Priced> repriced_;
  Planner planner_{eval_, topo_, mesh_.triangles.data(), nullptr, limits_, {}, false};
  UninitVector<float> priority_;
  // Written whole by the workers at the first prices (no serial fill first).
  UninitVector<float> fan_area_; // area of each vertex's faces (kept up to date with lazy_)
  UninitVector<float> normals_;  // unit vertex normals of the input surface, 3 a vertex
  // Per vertex, with lazy_: the candidate its last plan chose on its evaluated plane
  // (Patch::candidate; kNoCandidate: none, or another direction or a seam's). Written by the
  // thread planning the vertex, as its price is; a pop of an unchanged ring tries it first
  // (the ranking skipped: bench/ablation.md).
  mutable UninitVector<uint8_t> chosen_;
  std::vector<uint8_t> flags_; // vertex_flags.h
  void set_refused(uint32_t v, Reject why) { flip_refused_ += size_t(refuse(v, why)); }
  // Records v's last refusal; returns the change of flip_refused_ (parts count their own).
  ptrdiff_t refuse(uint32_t v, Reject why) {
    const ptrdiff_t change = ptrdiff_t(why == RejectFlip) - ptrdiff_t(refused(v) == RejectFlip);
    flags_[v] = uint8_t((flags_[v] & ~kRefusedMask) | (why << kRefusedShift));
    return change;
  }
  size_t flip_refused_ = 0; // vertices whose last plan a corner's input normal refused
  Reject refused(uint32_t v) const { return Reject((flags_[v] & kRefusedMask) >> kRefusedShift); }
  // Per face slot after the drop of faces with a repeated corner: its input face (empty: none
  // dropped, each its own). The run's slot f stands for kept_faces_[order_.face_old[f]] until
  // rewritten (kRewrittenSlot).
  UninitVector<uint32_t> kept_faces_;
  std::vector<uint32_t> corner_source_; // per face slot corner: the input corner it carries
  std::vector<float> face_bound_;       // per face slot: its certified error bound (max_error)
  CarriedPoints carried_;               // removed vertices, by the face standing for them
  InputSurface input_;                  // the input's faces, for fold-overs against it
  Constraints constraints_;
  SpatialOrder order_;
  Welding welding_; // split vertices welded for the run (Options::split_vertices)
  FanSplit fans_;   // vertices where fans meet, a copy a fan for the run (fan_split.h)
  // The vertex queued i-th: the input's order, then the copies of fan_split.h.
  uint32_t queue_order(size_t i) const {
    return i < order_.vertex_new.size() ? order_.vertex_new[i] : uint32_t(i);
  }
  // Per input face: turned over for the run only (pieces welded along edges both walked the
  // same way, Welding::same_way); output faces take it back. Empty: the run's orientation is
  // the output's.
  std::vector<uint8_t> turned_;
  TurnedSlots turned_slots() const { return {&turned_, &corner_source_}; } // by face slot
  size_t faces_ = 0, vertices_ = 0, target_faces_ = 0, target_vertices_ = 0;
  size_t faces0_ = 0;
  double reference_area_ = 1; // mean input triangle area (LocalError's weight)
};

// simplify() with its removals recorded for a progressive mesh (progressive.cpp): the log
// (Simplifier::removal_log_) and the faces standing after the run. Null: a plain run.
struct RemovalRecord {
  std::vector<uint32_t> log, base_slots, base_corners;
};
// For the benchmark (vrs_bench --serial): on one thread, what the run would take on 8 and 16,
// its loops each in rounds of their chunks (Workers::span_seconds), the rest as it was.
// Amdahl's bound without the chunks.
struct RunProjection {
  double seconds_8 = 0, seconds_16 = 0;
};
Report simplify_recorded(Mesh& mesh, const Options& options, RemovalRecord* record,
                         RunProjection* projection = nullptr);

} // namespace vrs
