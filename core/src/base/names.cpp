// Names of the enums, for reports, the CLI and the plugin.
#include "vrs/simplify.h"

namespace vrs {

const char* reject_name(Reject r) {
  switch (r) {
  case RejectFold: return "fold";
  case RejectEdge: return "edge_exists";
  case RejectTriangle: return "triangle_exists";
  case RejectFlip: return "flip";
  case RejectDegenerate: return "degenerate";
  case RejectFoldOver: return "fold_over";
  case RejectBound: return "error_bound";
  default: return "unknown";
  }
}

const char* stop_reason_name(StopReason r) {
  switch (r) {
  case StopReason::TargetReached: return "target_reached";
  case StopReason::MaxFactor: return "max_factor";
  case StopReason::LastInterval: return "last_interval";
  case StopReason::NoCandidates: return "no_candidates";
  case StopReason::Cancelled: return "cancelled";
  case StopReason::InvalidInput: return "invalid_input";
  case StopReason::ErrorBound: return "error_bound";
  }
  return "unknown";
}

const char* stop_cause_name(StopCause c) {
  switch (c) {
  case StopCause::None: return "none";
  case StopCause::PriceJump: return "price_jump";
  case StopCause::ErrorBound: return "error_bound";
  case StopCause::Vetoes: return "vetoes";
  case StopCause::Boundary: return "boundary";
  case StopCause::Constrained: return "constrained";
  case StopCause::SplitSeam: return "split_seam";
  case StopCause::Locked: return "locked";
  case StopCause::NonFinite: return "nonfinite";
  case StopCause::NonManifold: return "nonmanifold";
  case StopCause::HighValence: return "high_valence";
  case StopCause::NoPlane: return "no_plane";
  }
  return "unknown";
}

size_t Report::rejected_total() const {
  size_t n = 0;
  for (size_t r : rejected)
    n += r;
  return n;
}

bool parse_mode(const std::string& s, Mode& out) {
  if (s == "surface")
    out = Mode::Surface3D;
  else if (s == "terrain")
    out = Mode::Terrain25D;
  else if (s == "planar")
    out = Mode::Planar2D;
  else
    return false;
  return true;
}

bool parse_queue(const std::string& s, QueueKind& out) {
  if (s == "intervals")
    out = QueueKind::Intervals;
  else if (s == "heap")
    out = QueueKind::Heap;
  else
    return false;
  return true;
}

bool parse_mapping(const std::string& s, IntervalMapping& out) {
  if (s == "linear")
    out = IntervalMapping::Linear;
  else if (s == "log")
    out = IntervalMapping::Logarithmic;
  else
    return false;
  return true;
}

bool parse_priority(const std::string& s, Priority& out) {
  if (s == "factor")
    out = Priority::Factor;
  else if (s == "local-error")
    out = Priority::LocalError;
  else
    return false;
  return true;
}

const char* priority_name(Priority p) {
  return p == Priority::LocalError ? "local-error" : "factor";
}

bool parse_fill(const std::string& s, Fill& out) {
  if (s == "best")
    out = Fill::Best;
  else if (s == "projection")
    out = Fill::Projection;
  else
    return false;
  return true;
}

const char* fill_name(Fill f) {
  return f == Fill::Best ? "best" : "projection";
}

} // namespace vrs
