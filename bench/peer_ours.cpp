#include <chrono>
#include <string>

#include "driver/simplifier.h"
#include "peers.h"

namespace vrs_bench {

PeerResult run_ours(const vrs::Mesh& in, size_t target_faces, vrs::Options o) {
  PeerResult r;
  r.mesh = in;
  o.target.kind = vrs::TargetKind::Faces;
  o.target.faces = target_faces;
  MemoryProbe probe;
  const auto t0 = std::chrono::steady_clock::now();
  vrs::Report rep = vrs::simplify(r.mesh, o);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  probe.finish(r);
  r.error_bound = rep.error_bound;
  if (!rep.target_reached) {
    // The CSV's last column: the reason and what kept the rest, without commas.
    r.note = std::string(vrs::stop_reason_name(rep.stop)) + ": " + rep.stop_detail;
    for (char& c : r.note)
      if (c == ',') c = '/';
  }
  return r;
}

PeerResult run_ours_bound(const vrs::Mesh& in, double max_error, vrs::Options o) {
  o.max_error = max_error;
  return run_ours(in, 0, o);
}

vrs::Report run_ours_projected(vrs::Mesh& m, const vrs::Options& options, double& seconds_8,
                               double& seconds_16) {
  vrs::RunProjection projection;
  const vrs::Report r = vrs::simplify_recorded(m, options, nullptr, &projection);
  seconds_8 = projection.seconds_8;
  seconds_16 = projection.seconds_16;
  return r;
}

} // namespace vrs_bench
