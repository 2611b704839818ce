// MeshLab 2020.09's "Simplification: Quadric Edge Collapse Decimation", as filter_meshing runs
// it: the same vcglib collapse, parameters at the dialog's defaults, the same cleaning.
#include <chrono>

#include "bench_mesh.h" // vcglib's complex.h first

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/local_optimization.h>
#include <vcg/complex/algorithms/local_optimization/tri_edge_collapse_quadric.h>
#include <vcg/container/simple_temporary_data.h>

#include "peers.h"

namespace vrs_bench {

namespace {

using QuadricTemp = vcg::SimpleTempData<BenchMesh::VertContainer, vcg::math::Quadric<double>>;

struct QHelper {
  static void Init() {}
  static vcg::math::Quadric<double>& Qd(BVertex& v) { return TD()[v]; }
  static vcg::math::Quadric<double>& Qd(BVertex* v) { return TD()[*v]; }
  static float W(BVertex*) { return 1.0f; }
  static float W(BVertex&) { return 1.0f; }
  static void Merge(BVertex&, BVertex const&) {}
  static QuadricTemp*& TDp() {
    static QuadricTemp* td;
    return td;
  }
  static QuadricTemp& TD() { return *TDp(); }
};

using VertexPair = vcg::tri::BasicVertexPair<BVertex>;
class Collapse : public vcg::tri::TriEdgeCollapseQuadric<BenchMesh, VertexPair, Collapse, QHelper> {
 public:
  using Base = vcg::tri::TriEdgeCollapseQuadric<BenchMesh, VertexPair, Collapse, QHelper>;
  Collapse(const VertexPair& p, int i, vcg::BaseParameterClass* pp) : Base(p, i, pp) {}
};

} // namespace

PeerResult run_qecd(const vrs::Mesh& in, size_t target_faces, bool preserve_topology,
                    bool optimal_placement) {
  BenchMesh m;
  to_vcg(in, m);
  // Faces with a repeated corner (an STL's slivers welded shut) crash vcglib's collapse (Spider
  // from assimp's models); every method drops them (ours counts them in its report).
  vcg::tri::Clean<BenchMesh>::RemoveDegenerateFace(m);
  vcg::tri::Allocator<BenchMesh>::CompactEveryVector(m);
  PeerResult r;
  MemoryProbe probe;
  const auto t0 = std::chrono::steady_clock::now();
  vcg::tri::UpdateTopology<BenchMesh>::VertexFace(m);
  vcg::tri::UpdateFlags<BenchMesh>::FaceBorderFromVF(m);

  vcg::tri::TriEdgeCollapseQuadricParameter pp; // the dialog's defaults, as the filter sets them
  pp.QualityThr = 0.3;
  pp.PreserveBoundary = false;
  pp.BoundaryQuadricWeight = pp.BoundaryQuadricWeight * 0.5; // "BoundaryWeight" = 0.5
  pp.PreserveTopology = preserve_topology;
  pp.QualityWeight = false;
  pp.NormalCheck = false;
  pp.OptimalPlacement = optimal_placement;
  pp.QualityQuadric = false;
  pp.QualityQuadricWeight = 0.001;

  vcg::math::Quadric<double> zero;
  zero.SetZero();
  QuadricTemp td(m.vert, zero);
  QHelper::TDp() = &td;
  vcg::LocalOptimization<BenchMesh> session(m, &pp);
  session.Init<Collapse>();
  const int target = int(target_faces);
  session.SetTargetSimplices(target);
  session.SetTimeBudget(0.1f);
  while (session.DoOptimization() && m.fn > target) {
  }
  session.Finalize<Collapse>();
  QHelper::TDp() = nullptr;

  // "Post-simplification cleaning" (AutoClean, on by default).
  vcg::tri::Clean<BenchMesh>::RemoveFaceOutOfRangeArea(m, 0);
  vcg::tri::Clean<BenchMesh>::RemoveDuplicateVertex(m);
  vcg::tri::Clean<BenchMesh>::RemoveUnreferencedVertex(m);
  vcg::tri::Allocator<BenchMesh>::CompactEveryVector(m);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  probe.finish(r);
  r.mesh = from_vcg(m);
  return r;
}

} // namespace vrs_bench
