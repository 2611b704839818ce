// OpenMesh 9's Decimater with ModQuadricT (non-binary: a priority, no error limit), the
// vertex-keeping quadric decimation the class table names.
#include <chrono>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include "peers.h"

namespace vrs_bench {

namespace {
using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;
}

PeerResult run_openmesh(const vrs::Mesh& in, size_t target_faces) {
  PeerResult r;
  OMesh mesh;
  std::vector<OMesh::VertexHandle> vh(in.vertex_count());
  for (size_t v = 0; v < in.vertex_count(); ++v)
    vh[v] = mesh.add_vertex(
        OMesh::Point(in.positions[3 * v], in.positions[3 * v + 1], in.positions[3 * v + 2]));
  size_t refused = 0; // OpenMesh's half-edge structure takes manifold faces only
  for (size_t f = 0; f < in.face_count(); ++f) {
    const uint32_t* t = &in.triangles[3 * f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] ||
        !mesh.add_face(vh[t[0]], vh[t[1]], vh[t[2]]).is_valid())
      ++refused;
  }
  MemoryProbe probe;
  const auto t0 = std::chrono::steady_clock::now();
  OpenMesh::Decimater::DecimaterT<OMesh> decimater(mesh);
  OpenMesh::Decimater::ModQuadricT<OMesh>::Handle quadric;
  decimater.add(quadric);
  decimater.module(quadric).unset_max_err();
  decimater.initialize();
  decimater.decimate_to_faces(0, target_faces);
  mesh.garbage_collection();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  probe.finish(r);
  for (auto v : mesh.vertices()) {
    const OMesh::Point& p = mesh.point(v);
    r.mesh.positions.insert(r.mesh.positions.end(), {p[0], p[1], p[2]});
  }
  for (auto f : mesh.faces())
    for (auto v : mesh.fv_range(f))
      r.mesh.triangles.push_back(uint32_t(v.idx()));
  if (refused) r.note = std::to_string(refused) + " non-manifold input faces refused by OpenMesh";
  if (r.mesh.face_count() > target_faces + target_faces / 20)
    r.note += (r.note.empty() ? "" : "; ") + std::string("target not reached");
  return r;
}

} // namespace vrs_bench
