#include "remove/removal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "evaluate/local_error.h"

namespace vrs {

namespace {

// The ring's positions and their projections on the plane of `n`, relative to v.
void project(uint32_t v, const Ring& ring, Vec3 n, const Evaluator& eval, Patch& out) {
  plane_basis(n, out.u, out.w);
  const Vec3 c = eval.position(v);
  for (int i = 0; i < ring.verts; ++i) {
    out.q[i] = eval.position(ring.v[i]);
    Vec3 d = out.q[i] - c;
    out.p[i] = {dot(d, out.u), dot(d, out.w)};
  }
  out.normal = n;
  set_replaced_faces(c, ring, out);
}

} // namespace

bool star_direction(uint32_t v, const Ring& ring, const Evaluator& eval, Vec3& out) {
  const int k = ring.verts;
  const Vec3 c = eval.position(v);
  UnsetArray<Vec3, kMaxRing> n;
  Vec3 area, unit;
  for (int i = 0; i < ring.faces; ++i) {
    Vec3 a = cross(eval.position(ring.v[i]) - c, eval.position(ring.v[wrap(i + 1, k)]) - c);
    n[i] = normalized(a);
    area = area + a;
    unit = unit + n[i];
  }
  auto sees_star = [&](Vec3 d) {
    if (!(length(d) > 0)) return false;
    for (int i = 0; i < ring.faces; ++i)
      if (!(dot(n[i], d) > 1e-6)) return false;
    return true;
  };
  for (Vec3 d : {normalized(area), normalized(unit)})
    if (sees_star(d)) {
      out = d;
      return true;
    }
  for (int i = 0; i < ring.faces; ++i)
    if (sees_star(n[i])) {
      out = n[i];
      return true;
    }
  return false;
}

bool Planner::large_triangles_fold(const Patch& patch, uint64_t turned) const {
  const double twice = 2 * limits_->large_triangle_area; // the cross product's length
  for (int t = 0; t < patch.count; ++t) {
    const auto& tri = patch.tri[t];
    const Vec3 a = patch.q[tri[0]];
    if (length(cross(patch.q[tri[1]] - a, patch.q[tri[2]] - a)) >= twice)
      return input_->folded_area(patch, *eval_, limits_->large_triangle_area, limits_->fold_budget,
                                 turned) > limits_->fold_budget;
  }
  return false;
}

Reject Planner::plan(uint32_t v, const Ring& ring, Vec3 n, Patch& out, double& cost,
                     bool check_topology, OpenRing open, bool price, int hint, double lead) const {
  const int k = ring.verts;
  if (k < 3 && !(k == 2 && !ring.closed())) return RejectFold;
  project(v, ring, n, *eval_, out);
  const FaceNormals& replaced = out.face_n;
  // `shaped`: the shape veto already passed `out` (its corner unsure set).
  auto vetoed = [&](bool plane_angle, bool shaped = false) {
    // Topology first (it cannot change with the projection), then shape.
    Reject why = check_topology ? veto_topology(ring, out, open, *topo_, tris_) : RejectCount;
    if (!shaped) out.unsure_corners = 0;
    if (why == RejectCount && !shaped)
      why = veto_shape(ring, out, replaced, normals_, *limits_, plane_angle, &out.unsure_corners);
    // Judged against the input where the mesh look-ups are (the plan that commits), not in
    // every pricing pass: it walks every point the old faces carry (a tenth of the time).
    if (why == RejectCount && check_topology && carried_ &&
        carried_->folds_input(v, ring, out, *eval_, normals_))
      why = RejectFoldOver;
    // The eased passes ask it of every triangle (their corner test no longer holds); the
    // others, at four points, of triangles over eight input faces or more where the corners
    // are unsure (a triangle across a thread's crest stands nearer the next flank: asked of
    // the small ones too, the threads were lost and the tail grew; over two faces, on the
    // full grid, the tuning set folded less but took twice the time). Only unsure corners
    // ask: a smooth mesh never builds the input's hierarchy (ungated, the run takes several
    // times as long), and the benchmark folds as little as with a lower gate.
    // Large triangles (a small output's) are asked whatever their corners say, and refused
    // only past a budget of folded area: refused at any fold, the thin CAD shells' 10 % runs
    // lost more to the error than they gained.
    if (why == RejectCount && check_topology && input_) {
      const bool eased = limits_->folds_judged_by_input; // the vetoes eased, the input kept
      // Each new triangle as its first corner's face (the output writes it so).
      const uint64_t turned =
          turned_.triangles(out.count, [&](int t) { return ring.f[out.from[t][0]]; });
      const bool folds = eased ? input_->folds(out, *eval_, 0, InputSurface::kGridMax, turned)
                               : (out.unsure_corners && input_->folds(out, *eval_, input_covers_,
                                                                      kInputCheckSide, turned)) ||
                                     large_triangles_fold(out, turned);
      if (folds) why = RejectFoldOver;
    }
    // A seam's sides are bounded together, by plan_seam.
    if (why == RejectCount && face_bound_ && open == OpenRing::Border)
      why = veto_bound(ring, out, eval_->position(v), face_bound_, *limits_);
    return why;
  };
  const int candidates = candidate_count(ring, fans_);
  // A candidate is a hint for the next plan of the same ring only if every one ranked before it
  // was refused for the ring's own sake: an edge or a triangle found elsewhere in the mesh can
  // go while the ring stays as it is (the topology veto's two reasons; a veto that asks the
  // mesh beyond the ring must be counted here too).
  bool refused_by_mesh = false;
  // `priced`: the exact price of `out` as it stands, when already made (NaN: not).
  auto accept = [&](int c, double priced = std::numeric_limits<double>::quiet_NaN()) {
    out.candidate = refused_by_mesh ? kNoCandidate : uint8_t(c);
    cost = !price ? 0.0 : !std::isnan(priced) ? priced : price_.exact(v, ring, out);
    return RejectCount;
  };
  if (hint >= 0 && hint < candidates && fill_candidate(ring, open, hint, out) &&
      vetoed(hint == 0 || on_plane_) == RejectCount)
    return accept(hint);
  // Every candidate gets the cheap estimate; in its order, the first one no veto refuses is
  // planned and priced exactly. (Pricing each exactly chose about as well on the benchmark's
  // meshes, for far more time.) The projection's triangles are kept aside: ear clipping
  // is the one candidate that is dear to make twice. An estimate may stop once it is beyond
  // the best so far (a lower bound then): it is finished only if its turn comes, and the
  // order is the one the finished estimates give (ties to the lower candidate).
  std::array<double, kMaxRing + 2> estimate;
  std::array<bool, kMaxRing + 2> complete;
  std::array<uint8_t, kMaxRing + 2> listed;
  std::array<std::array<uint8_t, 3>, kMaxRing> projected;
  int projected_count = -1, m = 0;
  // The fan the projection made, when it made one (a convex ring): that fan's candidate has
  // the same triangles, in the same order, and so the same estimate.
  int twin = -1;
  double best = std::numeric_limits<double>::infinity();
  for (int c = 0; c < candidates; ++c) {
    if (c == twin) {
      estimate[c] = estimate[0];
      complete[c] = true;
      listed[m++] = uint8_t(c);
      continue;
    }
    if (!fill_triangles(ring, open, c, out)) {
      // On a fixed plane a fan triangulates the projected ring only where the ring is the
      // simple polygon the projection checks (then each of its triangles must face the plane).
      if (on_plane_) return RejectFold;
      continue;
    }
    if (c == 0) {
      projected = out.tri;
      projected_count = out.count;
      if (candidates > 1) twin = fan_candidate(ring, out);
    }
    complete[c] = true;
    estimate[c] = candidates > 1 ? price_.estimate(v, ring, out, best, complete[c]) : 0.0;
    if (complete[c]) best = std::min(best, estimate[c]);
    listed[m++] = uint8_t(c);
  }
  // The untried candidate of least (estimate, index); an unfinished estimate is finished first.
  auto next = [&]() {
    while (true) {
      int at = 0;
      for (int i = 1; i < m; ++i)
        if (estimate[listed[i]] < estimate[listed[at]] ||
            (estimate[listed[i]] == estimate[listed[at]] && listed[i] < listed[at]))
          at = i;
      const int c = listed[at];
      if (complete[c]) {
        listed[at] = listed[--m];
        return c;
      }
      fill_triangles(ring, open, c, out);
      estimate[c] =
          price_.estimate(v, ring, out, std::numeric_limits<double>::infinity(), complete[c]);
    }
  };
  Reject first_why = RejectCount;
  bool first =
      price && check_topology && !face_bound_ && lead < std::numeric_limits<double>::infinity();
  while (m > 0) {
    const int c = next();
    if (c == 0) {
      out.tri = projected;
      out.count = projected_count;
      set_corner_faces(ring, out);
    } else {
      fill_candidate(ring, open, c, out);
    }
    double priced = std::numeric_limits<double>::quiet_NaN();
    if (std::exchange(first, false)) {
      // The shape veto alone first (the corners' unsure price a crease): a plan that will not
      // lead is not asked the mesh's vetoes. The same price as after them (they write nothing).
      out.unsure_corners = 0;
      if (veto_shape(ring, out, replaced, normals_, *limits_, c == 0 || on_plane_,
                     &out.unsure_corners) == RejectCount) {
        priced = price_.exact(v, ring, out);
        if (priced > lead) {
          out.candidate = uint8_t(c);
          cost = priced;
          return RejectCount;
        }
      }
    }
    const Reject why = vetoed(c == 0 || on_plane_, !std::isnan(priced));
    if (why == RejectCount) return accept(c, priced);
    if (first_why == RejectCount) first_why = why;
    refused_by_mesh |= why == RejectEdge || why == RejectTriangle;
  }
  // Every fan and the projection has a triangle some veto refuses: in the last resort, look
  // among all the ring's triangulations for one without (ranked by their triangles' distance
  // to the old fan). Only there: offered from the start it measured a wash for more time, and
  // this way a run that never needs the last resort is what it was without it.
  // Closed rings only: on a border ring the new border edge leaves its triangles freer than
  // the old fan can judge (the fuzzer found one folding there over the input).
  if (limits_->least_cost_filling && fans_ && !on_plane_ && ring.closed() && k >= 4) {
    const OldFan fan(v, ring, out, *eval_);
    auto triangle_cost = [&](int a, int b, int c) {
      const std::array<uint8_t, 3> tri{uint8_t(a), uint8_t(b), uint8_t(c)};
      if (veto_triangle(ring, out, tri, replaced, normals_, *limits_, false) != RejectCount)
        return std::numeric_limits<double>::infinity();
      // Free to span the ring, a triangle's one ring edge says little about where its middle
      // lies: the old faces around its centroid must not all face against it (a fold-over as
      // tests/support/fold_over.h counts one, with the old fan standing for the input).
      const Vec3 x = out.q[a], y = out.q[b], z = out.q[c];
      const double edge = std::max({length(y - x), length(z - y), length(x - z)});
      if (fan.opposes_near((x + y + z) * (1.0 / 3), normalized(cross(y - x, z - x)), 0.5 * edge))
        return std::numeric_limits<double>::infinity();
      return triangle_error2(fan, ring, out, a, b, c);
    };
    auto diagonal_ok = [&](int a, int b) {
      return !check_topology || !topo_->has_edge(ring.v[a], ring.v[b], tris_);
    };
    if (fill_least_cost(ring, triangle_cost, diagonal_ok, out)) {
      set_corner_faces(ring, out);
      if (vetoed(false) == RejectCount) // a triangle that exists already, or the bound
        return accept(kNoCandidate);
    }
  }
  return first_why == RejectCount ? RejectFold : first_why;
}

Reject Planner::plan_seam(uint32_t v, const Ring& ring, int i, int j, Vec3 n, Patch& out,
                          double& cost, bool check_topology, bool price) const {
  const int k = ring.verts;
  // Two faces back to back (a fin: both sides one triangle) have no side left to fill.
  if (k < 3) return RejectFold;
  Patch side;
  int count = 0;
  cost = 0;
  // Side 0 runs from ring[i] to ring[j] counter-clockwise, side 1 from ring[j] back to ring[i].
  for (int s = 0; s < 2; ++s) {
    const int first = s == 0 ? i : j, m = (s == 0 ? j - i : k - j + i) + 1;
    if (m < 3) continue; // one triangle on this side: it goes, the chord is its ring edge
    const bool on_edge = (s == 0 ? k - j + i : j - i) == 1;
    Ring sub;
    sub.verts = m;
    sub.faces = m - 1;
    for (int r = 0; r < m; ++r)
      sub.v[r] = ring.v[(first + r) % k];
    for (int r = 0; r + 1 < m; ++r)
      sub.f[r] = ring.f[(first + r) % k];
    // A side is priced by its own error; the bound is the whole patch's, made below (the
    // price's bound term read these, unset: the run differed from one process to the next).
    side.bound.fill(0.0f);
    double side_cost = 0;
    Reject why = plan(v, sub, n, side, side_cost, check_topology,
                      on_edge ? OpenRing::SeamSideOnEdge : OpenRing::SeamSide, price);
    if (why != RejectCount) return why;
    cost = std::max(cost, side_cost);
    for (int t = 0; t < side.count; ++t, ++count)
      for (int c = 0; c < 3; ++c) {
        out.tri[count][c] = static_cast<uint8_t>((first + side.tri[t][c]) % k);
        out.from[count][c] = static_cast<uint8_t>((first + side.from[t][c]) % k);
      }
  }
  out.count = count;
  out.candidate = kNoCandidate;
  project(v, ring, n, *eval_, out);
  if (face_bound_ && !ring.closed()) return RejectBound;
  if (face_bound_) {
    const Reject why = veto_bound(ring, out, eval_->position(v), face_bound_, *limits_);
    if (why == RejectCount && price) // as Simplifier::price weighs a patch bounded whole
      for (int t = 0; t < out.count; ++t)
        cost = std::max(cost, double(out.bound[t]));
    return why;
  }
  return RejectCount;
}

} // namespace vrs
