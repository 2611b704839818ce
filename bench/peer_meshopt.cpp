#include <chrono>

#include <meshoptimizer.h>

#include "peers.h"

namespace vrs_bench {

namespace {

// `target_error` is relative to the mesh's extent, as meshoptimizer takes it.
PeerResult simplify(const vrs::Mesh& in, size_t target_faces, float target_error) {
  PeerResult r;
  std::vector<unsigned int> out(in.triangles.size());
  float error = 0;
  MemoryProbe probe;
  const auto t0 = std::chrono::steady_clock::now();
  size_t n = meshopt_simplify(out.data(), in.triangles.data(), in.triangles.size(),
                              in.positions.data(), in.vertex_count(), 3 * sizeof(float),
                              3 * target_faces, target_error, 0, &error);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  probe.finish(r);
  out.resize(n);
  // Keep only the vertices used (not timed: meshoptimizer leaves that to its caller).
  std::vector<uint32_t> remap(in.vertex_count(), vrs::kRemoved);
  for (unsigned int& i : out) {
    if (remap[i] == vrs::kRemoved) {
      remap[i] = uint32_t(r.mesh.positions.size() / 3);
      r.mesh.positions.insert(r.mesh.positions.end(), &in.positions[3 * size_t(i)],
                              &in.positions[3 * size_t(i)] + 3);
    }
    i = remap[i];
  }
  r.mesh.triangles.assign(out.begin(), out.end());
  if (r.mesh.face_count() > target_faces) r.note = "target not reached";
  return r;
}

} // namespace

PeerResult run_meshopt(const vrs::Mesh& in, size_t target_faces) {
  // target_error 1 (the whole extent): no error limit, the face count decides, as for the others.
  return simplify(in, target_faces, 1.0f);
}

PeerResult run_meshopt_bound(const vrs::Mesh& in, double max_error) {
  const float scale =
      meshopt_simplifyScale(in.positions.data(), in.vertex_count(), 3 * sizeof(float));
  PeerResult r = simplify(in, 0, float(max_error / (scale > 0 ? scale : 1.0f)));
  r.note.clear();
  return r;
}

} // namespace vrs_bench
