#include "surface_error.h"

#include <cmath>

#include "bench_mesh.h" // vcglib's complex.h first: point_sampling.h depends on it

#include <vcg/complex/algorithms/closest.h>
#include <vcg/complex/algorithms/point_sampling.h>
#include <vcg/space/index/grid_static_ptr.h>

#include <numeric>
#include <random>

#include "mesh/orientation.h" // the core's
#include "mesh/topology.h"

namespace vrs_bench {

namespace {

struct OneWay {
  double max = 0, sum = 0, sum_sq = 0;
  size_t n = 0;
};

OneWay one_way(BenchMesh& sampled, BenchMesh& target, size_t samples) {
  vcg::tri::HausdorffSampler<BenchMesh> hs(&target);
  // The grid over both meshes' box, 1 % larger: with the faces' own box, a sample a rounding
  // error inside its far side is mapped one cell past the grid (vcglib 2020.09 reads out of
  // bounds and crashed on the 4.8 M-face Loop bunny), and a sample far outside a grid of a few
  // faces crashed its search (blob at 1 %: 3 faces).
  vcg::Box3f box = target.bbox;
  box.Add(sampled.bbox);
  box.Offset(0.01f * box.Diag());
  hs.unifGridFace.Set(target.face.begin(), target.face.end(), box);
  hs.dist_upper_bound = std::numeric_limits<float>::max();
  using Sampling = vcg::tri::SurfaceSampling<BenchMesh, vcg::tri::HausdorffSampler<BenchMesh>>;
  Sampling::SamplingRandomGenerator().initialize(0); // same samples every run
  Sampling::VertexUniform(sampled, hs, sampled.vn);
  Sampling::Montecarlo(sampled, hs, int(samples));
  OneWay r;
  r.max = hs.getMaxDist();
  r.n = size_t(hs.n_total_samples);
  r.sum = hs.getMeanDist() * double(r.n);
  r.sum_sq = hs.getRMSDist() * hs.getRMSDist() * double(r.n);
  return r;
}

} // namespace

SurfaceError surface_error(const vrs::Mesh& a, const vrs::Mesh& b, size_t samples_per_side) {
  BenchMesh ma, mb;
  to_vcg(a, ma);
  to_vcg(b, mb);
  OneWay ab = one_way(ma, mb, samples_per_side), ba = one_way(mb, ma, samples_per_side);
  SurfaceError e;
  e.diagonal = ma.bbox.Diag();
  e.samples = ab.n + ba.n;
  const double d = e.diagonal > 0 ? e.diagonal : 1.0;
  e.max = std::max(ab.max, ba.max) / d;
  e.mean = (ab.sum + ba.sum) / double(e.samples) / d;
  e.rms = std::sqrt((ab.sum_sq + ba.sum_sq) / double(e.samples)) / d;
  return e;
}

double fold_over_share(const vrs::Mesh& original, const vrs::Mesh& simplified, size_t samples) {
  // An input written with its faces in random orientation has no side to fold over against:
  // it is read oriented coherently, each piece as most of its faces were (the convention of
  // the core's orientation.h), for every method alike.
  vrs::Mesh reference = original;
  {
    vrs::Topology topo;
    topo.build(reference.triangles, reference.vertex_count());
    std::vector<uint32_t> rank(reference.face_count());
    std::iota(rank.begin(), rank.end(), 0u);
    std::vector<uint8_t> reversed;
    vrs::orient_coherently(reference.triangles, topo, rank.data(), reversed);
  }
  BenchMesh a;
  to_vcg(reference, a);
  vcg::tri::UpdateNormal<BenchMesh>::PerFaceNormalized(a);
  vcg::Box3f box = a.bbox;
  box.Offset(0.01f * box.Diag());
  vcg::GridStaticPtr<BFace, float> grid;
  grid.Set(a.face.begin(), a.face.end(), box);
  // Samples spread by area over the simplified faces (cumulative area, fixed seed).
  const auto& p = simplified.positions;
  const auto& t = simplified.triangles;
  const size_t n = t.size() / 3;
  std::vector<double> cumulative(n + 1, 0.0);
  auto at = [&](uint32_t v) { return vcg::Point3f(p[3 * v], p[3 * v + 1], p[3 * v + 2]); };
  for (size_t f = 0; f < n; ++f) {
    vcg::Point3f x = at(t[3 * f]), y = at(t[3 * f + 1]), z = at(t[3 * f + 2]);
    double area = ((y - x) ^ (z - x)).Norm() * 0.5;
    cumulative[f + 1] = cumulative[f] + (std::isfinite(area) ? area : 0.0);
  }
  if (!(cumulative[n] > 0) || a.fn == 0) return 0.0;
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  size_t folded = 0;
  const float reach = a.bbox.Diag();
  for (size_t s = 0; s < samples; ++s) {
    const double r = unit(rng) * cumulative[n];
    size_t f =
        size_t(std::upper_bound(cumulative.begin(), cumulative.end(), r) - cumulative.begin());
    f = std::min(n, std::max<size_t>(f, 1)) - 1;
    vcg::Point3f x = at(t[3 * f]), y = at(t[3 * f + 1]), z = at(t[3 * f + 2]);
    double b1 = unit(rng), b2 = unit(rng);
    if (b1 + b2 > 1) b1 = 1 - b1, b2 = 1 - b2;
    vcg::Point3f q = x + (y - x) * float(b1) + (z - x) * float(b2);
    vcg::Point3f normal = ((y - x) ^ (z - x)).Normalize();
    float dist = reach;
    vcg::Point3f closest;
    BFace* nearest = vcg::tri::GetClosestFaceBase(a, grid, q, reach, dist, closest);
    if (nearest && normal.dot(nearest->N()) < 0) ++folded;
  }
  return double(folded) / double(samples);
}

} // namespace vrs_bench
