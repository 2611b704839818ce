// A vertex's price: its plane, the removal planned on it (removal.h) and what that costs.
#include <limits>

#include "driver/simplifier.h"
#include "evaluate/local_error.h"

namespace vrs {

Simplifier::Along Simplifier::along(uint32_t v, const Ring& ring, std::array<int, 2>& seam) const {
  const int degree = constraints_.degree(v);
  if (degree == 0) return Along::Free;
  return constraints_.seam_of(v, ring, seam[0], seam[1]) ? Along::Seam : Along::Kept;
}

Evaluation Simplifier::evaluate_plane(uint32_t v, const Ring& ring, double* chord) const {
  Evaluation e = eval_.evaluate(v, ring, simplify_boundary_);
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
  if (opt_.tuning.priority == Priority::Factor || !std::isfinite(e.factor)) return {e.factor};
  Patch patch;
  double cost = 0;
  // The mesh look-ups wait for the pop, where the plan is made again in full.
  Reject why = plan(v, ring, e, patch, cost, /*check_topology=*/false);
  if (why != RejectCount) // not queued; evaluated again when its ring changes
    return {std::numeric_limits<double>::infinity(), why, true};
  return {std::max(cost, chord), RejectCount, true};
}

Simplifier::Priced Simplifier::price_now(uint32_t v) const {
  Ring ring;
  const VertexKind kind = topo_.ring(v, mesh_.triangles.data(), opt_.max_valence, ring);
  return removable(kind) ? evaluate(v, ring) : Priced{std::numeric_limits<double>::infinity()};
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
  // first (fewer faces at the same bound).
  double worst = 0;
  for (int t = 0; t < patch.count; ++t)
    worst = std::max(worst, double(patch.bound[t]));
  return std::max(local, worst);
}

double Simplifier::estimate(const void* self, uint32_t v, const Ring&, const Patch& patch,
                            double cap, bool& complete) {
  return drop_height(v, patch, static_cast<const Simplifier*>(self)->eval_, cap, complete);
}

Reject Simplifier::plan(uint32_t v, const Ring& ring, const Evaluation& e, Patch& patch,
                        double& cost, bool check_topology, bool price, bool hinted,
                        double lead) const {
  std::array<int, 2> seam;
  const bool on_seam = along(v, ring, seam) == Along::Seam;
  const int hint = hinted && lazy_ && chosen_[v] != kNoCandidate ? chosen_[v] : -1;
  auto attempt = [&](Vec3 d, int first) {
    return on_seam ? planner_.plan_seam(v, ring, seam[0], seam[1], d, patch, cost, check_topology,
                                        price)
                   : planner_.plan(v, ring, d, patch, cost, check_topology, OpenRing::Border, price,
                                   first, lead);
  };
  Reject why = attempt(e.normal, hint);
  const bool first_direction = why == RejectCount && !on_seam;
  // At tips, creases and thin parts the average plane of a strongly curved ring can fold it
  // or tilt the patch away, while another direction still sees the ring as a star.
  if ((why == RejectFold || why == RejectFlip) && opt_.mode == Mode::Surface3D) {
    Vec3 d;
    if (star_direction(v, ring, eval_, d)) why = attempt(d, -1);
  }
  if (lazy_) chosen_[v] = first_direction ? patch.candidate : kNoCandidate;
  return why;
}

} // namespace vrs
