#include <cstdio>
#include <string>

#include "json_text.h"
#include "vrs/simplify.h"

namespace vrs {

namespace {

void add(std::string& out, const char* key, const std::string& json_value) {
  out += out.size() > 1 ? ",\"" : "\"";
  out += key;
  out += "\":";
  out += json_value;
}

std::string number(size_t n) {
  return std::to_string(n);
}

// Round-trips a double: a reader gets the value the run had.
std::string number(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

std::string boolean(bool b) {
  return b ? "true" : "false";
}
std::string text(const std::string& s) {
  return "\"" + vrs_common::json_text(s) + "\"";
}

} // namespace

std::string report_json(const Report& r, const ReportContext& c) {
  std::string out = "{";
  add(out, "ok", boolean(r.ok));
  add(out, "stop_reason", text(stop_reason_name(r.stop)));
  add(out, "stop_cause", text(stop_cause_name(r.stop_cause)));
  add(out, "target_reached", boolean(r.target_reached));
  add(out, "stop_detail", text(r.stop_detail));
  add(out, "message", text(r.message));
  add(out, "input_vertices", number(r.input_vertices));
  add(out, "input_faces", number(r.input_faces));
  add(out, "output_vertices", number(r.vertices));
  add(out, "output_faces", number(r.faces));
  add(out, "target_faces", number(r.target_faces));
  add(out, "target_vertices", number(r.target_vertices));
  add(out, "removed", number(r.removed));
  std::string rejected = "{";
  for (int i = 0; i < RejectCount; ++i)
    add(rejected, reject_name(Reject(i)), number(r.rejected[i]));
  add(out, "rejected", rejected + "}");
  add(out, "rejected_total", number(r.rejected_total()));
  std::string kept = "{";
  add(kept, "boundary", number(r.kept_boundary));
  add(kept, "nonmanifold", number(r.kept_nonmanifold));
  add(kept, "locked", number(r.kept_locked));
  add(kept, "high_valence", number(r.kept_high_valence));
  add(kept, "constrained", number(r.kept_constrained));
  add(out, "kept", kept + "}");
  add(out, "constrained_edges", number(r.constrained_edges));
  std::string input = "{";
  add(input, "degenerate_faces", number(r.dropped_degenerate_faces));
  add(input, "nonfinite_vertices", number(r.nonfinite_vertices));
  add(input, "unreferenced_vertices", number(r.unreferenced_vertices));
  add(input, "reoriented_faces", number(r.reoriented_faces));
  add(input, "welded_vertices", number(r.welded_vertices));
  add(out, "input_issues", input + "}");
  add(out, "relaxed_removals", number(r.relaxed_removals));
  add(out, "slid", number(r.slid));
  add(out, "boundary_simplified", boolean(r.boundary_simplified));
  add(out, "max_removed_factor", number(r.max_removed_factor));
  // A bound that was not tracked is absent, never 0 (which would read "no error at all").
  if (c.bounded) {
    add(out, "error_bound", number(r.error_bound));
    add(out, "error_bound_percent",
        number(c.diagonal > 0 ? 100.0 * r.error_bound / c.diagonal : 0.0));
  }
  add(out, "seconds_simplify", number(c.seconds_simplify));
  if (c.seconds_total >= 0) add(out, "seconds_total", number(c.seconds_total));
  return out + "}";
}

} // namespace vrs
