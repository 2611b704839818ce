// Plans the removal of one vertex: projects its ring, lets each candidate filling
// (candidates.h) make a patch, drops those a veto refuses (vetoes.h) and keeps the cheapest of
// the rest by the given price. Nothing is written; the driver commits an accepted plan.
#pragma once

#include "evaluate/carried_points.h"
#include "evaluate/evaluation.h"
#include "evaluate/input_surface.h"
#include "fill/candidates.h"
#include "fill/triangulation.h"
#include "mesh/topology.h"
#include "remove/vetoes.h"
#include "vrs/simplify.h"

namespace vrs {

// A direction on which every triangle around v projects counter-clockwise, tried among the
// fan's area-weighted normal, the mean of its unit normals and each triangle's own normal.
bool star_direction(uint32_t v, const Ring& ring, const Evaluator& eval, Vec3& out);

// What a candidate patch costs (the priority's view of it); lower is better. `estimate` ranks
// the candidates cheaply, `exact` prices the one planned (the vertex's priority).
// The estimate may stop once it is sure to exceed `cap` (a candidate already ranked costs
// that): it then returns what it has so far, a lower bound, with `complete` false.
struct Pricer {
  using Fn = double (*)(const void* ctx, uint32_t v, const Ring& ring, const Patch& patch);
  using EstimateFn = double (*)(const void* ctx, uint32_t v, const Ring& ring, const Patch& patch,
                                double cap, bool& complete);
  EstimateFn estimate_fn = nullptr;
  Fn exact_fn = nullptr;
  const void* ctx = nullptr;
  double estimate(uint32_t v, const Ring& ring, const Patch& patch, double cap,
                  bool& complete) const {
    return estimate_fn(ctx, v, ring, patch, cap, complete);
  }
  double exact(uint32_t v, const Ring& ring, const Patch& patch) const {
    return exact_fn(ctx, v, ring, patch);
  }
};

class Planner {
 public:
  // `surface_normals` holds the input's unit vertex normals (3 floats a vertex); `tris` is the
  // live triangle array. `fans`: the fans are candidates too (else only the projection).
  // `on_plane`: every patch must project on the plane as the ring does (terrains stay height
  // fields, planar meshes planar), so fans answer to the plane's vetoes as well.
  Planner(const Evaluator& eval, const Topology& topo, const uint32_t* tris,
          const float* surface_normals, const RemovalLimits& limits, Pricer price, bool fans,
          bool on_plane = false)
      : eval_(&eval), topo_(&topo), tris_(tris), normals_(surface_normals), limits_(&limits),
        price_(price), fans_(fans), on_plane_(on_plane) {}

  // Returns RejectCount when some candidate is valid (the best ranked is in `out`, its exact
  // price in `cost`), else why the best ranked was refused (RejectFold: none could be made).
  // `check_topology` = false skips the mesh look-ups (new triangle / edge already there): a pass
  // for the priority only, redone in full when the vertex is popped. `price` = false skips the
  // exact price (`cost` is then 0): the pop of a vertex whose price is still today's.
  // `hint`: the candidate a plan of the same ring on the same plane chose (Patch::candidate),
  // tried first; if no veto refuses it, it is what the whole plan would choose (the vetoes
  // refused the ones ranked before it then for the ring's own sake, and refuse them still), and
  // the ranking is skipped.
  // `lead`: the price under which the plan would be committed (the queue's next). A first
  // ranked candidate the shape veto passes and priced above it is returned as planned without
  // the vetoes that ask the mesh (topology, the carried input, the input's faces): the caller
  // pushes it back, and its next plan, the hint's, asks them (most plans of a stale price are
  // pushed back: a sixth of a run's time at 1.2 M faces was their mesh vetoes).
  Reject plan(uint32_t v, const Ring& ring, Vec3 normal, Patch& out, double& cost,
              bool check_topology = true, OpenRing open = OpenRing::Border, bool price = true,
              int hint = -1, double lead = std::numeric_limits<double>::infinity()) const;

  // The removal of a vertex on exactly two constrained edges, to ring positions i < j: the ring
  // is cut along the polyline (ring[i], v, ring[j]) and each side is planned as an open ring
  // closed by the chord (ring[i], ring[j]), which replaces the two constrained edges. `out` is
  // a patch of the whole ring, as plan's; `cost` the larger of the two sides'.
  Reject plan_seam(uint32_t v, const Ring& ring, int i, int j, Vec3 normal, Patch& out,
                   double& cost, bool check_topology = true, bool price = true) const;

  // Tracks the error bound (vetoes.h, veto_bound): each face slot's certified bound, kept by
  // the driver. nullptr: not tracked.
  void set_face_bounds(const float* face_bound) { face_bound_ = face_bound; }
  // Judges fold-overs against the input (CarriedPoints::folds_input) too. nullptr: not.
  void set_carried(const CarriedPoints* carried) { carried_ = carried; }
  // Judges fold-overs against the input's nearest faces too (InputSurface::folds): every
  // triangle in the eased passes, elsewhere those over kInputCheckCovers input faces (any,
  // where `turned` holds pieces) whose corners' normals are unsure, at most kInputCheckSide
  // grid cells a side, and, whatever their corners, those of limits.large_triangle_area,
  // refused past limits.fold_budget of folded area. nullptr: not.
  void set_input(const InputSurface* input, TurnedSlots turned = {}) {
    input_ = input;
    turned_ = turned;
    // Where pieces are held turned from how they were written, the corners' normals are the
    // run's, blind to a fold as written: where they doubt, small triangles are asked too.
    input_covers_ = turned.any() ? 0.0 : kInputCheckCovers;
  }
  static constexpr double kInputCheckCovers = 8.0;
  static constexpr int kInputCheckSide = 2;

 private:
  // Whether the patch's triangles of limits.large_triangle_area fold over more than
  // limits.fold_budget of area (none that large: false, the input not asked).
  bool large_triangles_fold(const Patch& patch, uint64_t turned) const;
  const Evaluator* eval_;
  const Topology* topo_;
  const uint32_t* tris_;
  const float* normals_;
  const RemovalLimits* limits_;
  Pricer price_;
  bool fans_, on_plane_;
  const float* face_bound_ = nullptr;
  const CarriedPoints* carried_ = nullptr;
  const InputSurface* input_ = nullptr;
  TurnedSlots turned_;
  double input_covers_ = kInputCheckCovers; // set_input's: the least a triangle asked covers
};

} // namespace vrs
