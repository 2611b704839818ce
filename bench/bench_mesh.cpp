#include "bench_mesh.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

namespace vrs_bench {

void to_vcg(const vrs::Mesh& in, BenchMesh& m) {
  m.Clear();
  auto vi = vcg::tri::Allocator<BenchMesh>::AddVertices(m, in.vertex_count());
  for (size_t v = 0; v < in.vertex_count(); ++v, ++vi)
    vi->P() = vcg::Point3f(in.positions[3 * v], in.positions[3 * v + 1], in.positions[3 * v + 2]);
  auto fi = vcg::tri::Allocator<BenchMesh>::AddFaces(m, in.face_count());
  for (size_t f = 0; f < in.face_count(); ++f, ++fi)
    for (int k = 0; k < 3; ++k)
      fi->V(k) = &m.vert[in.triangles[3 * f + k]];
  vcg::tri::UpdateBounding<BenchMesh>::Box(m);
  vcg::tri::UpdateNormal<BenchMesh>::PerFaceNormalized(m);
}

vrs::Mesh from_vcg(const BenchMesh& m) {
  vrs::Mesh out;
  std::vector<uint32_t> index(m.vert.size(), 0);
  uint32_t n = 0;
  for (size_t v = 0; v < m.vert.size(); ++v) {
    if (m.vert[v].IsD()) continue;
    index[v] = n++;
    for (int k = 0; k < 3; ++k)
      out.positions.push_back(m.vert[v].cP()[k]);
  }
  for (const BFace& f : m.face) {
    if (f.IsD()) continue;
    for (int k = 0; k < 3; ++k)
      out.triangles.push_back(index[vcg::tri::Index(m, f.cV(k))]);
  }
  return out;
}

} // namespace vrs_bench
