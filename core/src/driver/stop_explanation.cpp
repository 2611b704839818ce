#include "driver/stop_explanation.h"

#include <algorithm>
#include <cstdio>

#include "driver/simplifier.h"

namespace vrs {

std::string explain_remaining(const Remaining& r, bool simplify_boundary, bool last_resort) {
  std::string out;
  auto add = [&](size_t count, const std::string& what) {
    if (!count) return;
    out += (out.empty() ? "" : "; ") + std::to_string(count) + " " + what;
  };
  add(r.boundary, simplify_boundary ? "on the boundary in a single triangle"
                                    : "on the boundary, kept (boundary simplification is off)");
  add(r.corners, "at corners of the outline");
  add(r.constrained, "on seams or creases where they end, meet or cross");
  add(r.locked, "locked");
  add(r.nonfinite, "with a NaN or infinite coordinate, or next to one (kept, as every plane "
                   "through them is undefined)");
  add(r.split_seam, "on a seam of split vertices, kept (simplified apart, its two sides would "
                    "open a crack)");
  add(r.nonmanifold, "non-manifold or inconsistently oriented");
  add(r.high_valence, "of too high valence");
  std::string vetoes;
  for (int i = 0; i < RejectCount; ++i)
    if (r.refused[i])
      vetoes += (vetoes.empty() ? "" : ", ") + std::string(reject_name(Reject(i))) + " " +
                std::to_string(r.refused[i]);
  size_t total_refused = 0;
  for (size_t n : r.refused)
    total_refused += n;
  add(total_refused, "refused by the vetoes (" + vetoes + ")");
  if (last_resort && r.refused[RejectFoldOver])
    out += "; the last resort stopped: every filling left for " +
           std::to_string(r.refused[RejectFoldOver]) +
           " of them would fold the surface over (against the faces it replaces or the input "
           "nearest it)";
  add(r.untried, "without a usable plane (degenerate or non-finite neighbourhood)");
  // A soup of faces (every edge written twice) is all seams in Seam mode: say what welds it.
  if (r.constrained + r.split_seam > 0 && 2 * r.split_seam_edges > r.constrained_edges)
    out += "; most seams are where split vertices meet (" + std::to_string(r.split_seam_edges) +
           " of " + std::to_string(r.constrained_edges) +
           " edges): if their copies hold nothing of their own, split_vertices weld welds them "
           "freely";
  return "remaining vertices: " + (out.empty() ? std::string("none") : out);
}

bool Simplifier::next_to_nonfinite(uint32_t v, const Ring& ring) const {
  if (!rep_.nonfinite_vertices) return false;
  if (!is_finite(eval_.position(v))) return true;
  for (int i = 0; i < ring.verts; ++i)
    if (!is_finite(eval_.position(ring.v[i]))) return true;
  return false;
}

Remaining Simplifier::count_remaining() const {
  Remaining r;
  Ring ring;
  std::array<int, 2> seam;
  for (uint32_t v = 0; v < mesh_.vertex_count(); ++v) {
    if (flags_[v] & kFlagRemoved || topo_.valence(v) == 0) continue;
    VertexKind kind = topo_.ring(v, mesh_.triangles.data(), opt_.max_valence, ring);
    if (flags_[v] & kFlagTwin)
      ++r.split_seam;
    else if (flags_[v] & kFlagLocked)
      ++(next_to_nonfinite(v, ring) ? r.nonfinite : r.locked);
    else if (kind == VertexKind::NonManifold)
      ++r.nonmanifold;
    else if (kind == VertexKind::HighValence)
      ++r.high_valence;
    else if (!removable(kind))
      ++r.boundary;
    else if (along(v, ring, seam) == Along::Kept)
      ++r.constrained;
    else if (refused(v) != RejectCount)
      ++r.refused[refused(v)];
    else if (kind == VertexKind::Boundary)
      ++r.corners;
    else
      ++r.untried;
  }
  if (opt_.split_vertices == SplitVertices::Seam) r.split_seam_edges = welding_.seams.size() / 2;
  r.constrained_edges = rep_.constrained_edges;
  return r;
}

StopCause main_cause(const Remaining& r) {
  size_t refused = 0;
  for (size_t n : r.refused)
    refused += n;
  // In the order the words list them: the first of the largest groups names the cause.
  const std::pair<size_t, StopCause> groups[] = {{r.boundary + r.corners, StopCause::Boundary},
                                                 {r.constrained, StopCause::Constrained},
                                                 {r.locked, StopCause::Locked},
                                                 {r.nonfinite, StopCause::NonFinite},
                                                 {r.split_seam, StopCause::SplitSeam},
                                                 {r.nonmanifold, StopCause::NonManifold},
                                                 {r.high_valence, StopCause::HighValence},
                                                 {refused, StopCause::Vetoes},
                                                 {r.untried, StopCause::NoPlane}};
  std::pair<size_t, StopCause> most{0, StopCause::None};
  for (const auto& g : groups)
    if (g.first > most.first) most = g;
  return most.second;
}

void Simplifier::explain_stop() {
  if (jump_price_ > 0) {
    // The jump is measured from the dearest removal, or from the floor when that is higher
    // (jumps()): the words name the one it was measured from.
    const char* when = eased() ? "before the vetoes were eased" : "so far";
    char from[160];
    if (jump_from_ >= jump_floor_)
      std::snprintf(from, sizeof from, "the dearest made %s (%.3g)", when, jump_from_);
    else
      std::snprintf(from, sizeof from,
                    "a thousandth of the bounding box's diagonal (%.3g; the dearest made %s: "
                    "%.3g)",
                    jump_floor_, when, jump_from_);
    char why[640];
    std::snprintf(why, sizeof why,
                  "stopped short of the target: the cheapest removal left costs %.3g, %.0f times "
                  "%s; the surface would change abruptly (a part dropped, a tunnel pressed flat, "
                  "a thin wall crossed) rather than lose detail (max_jump, --max-jump: %g%s; 0 "
                  "reaches the target at any cost)",
                  jump_price_, jump_price_ / std::max(jump_from_, jump_floor_), from,
                  opt_.max_price_jump, eased() ? ", half of it once eased" : "");
    rep_.stop_detail = why;
    rep_.stop_cause = StopCause::PriceJump;
    return;
  }
  const Remaining r = count_remaining();
  rep_.stop_detail = explain_remaining(r, simplify_boundary_, last_resort());
  rep_.stop_cause = rep_.stop == StopReason::ErrorBound ? StopCause::ErrorBound : main_cause(r);
}

} // namespace vrs
