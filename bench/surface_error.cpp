#include "surface_error.h"

#include <cmath>

#include "bench_mesh.h" // vcglib's complex.h first: point_sampling.h depends on it

#include <vcg/complex/algorithms/point_sampling.h>

namespace vrs_bench {

namespace {

struct OneWay {
  double max = 0, sum = 0, sum_sq = 0;
  size_t n = 0;
};

OneWay one_way(BenchMesh& sampled, BenchMesh& target, size_t samples) {
  vcg::tri::HausdorffSampler<BenchMesh> hs(&target);
  // The grid again, over a box 1 % larger: with the faces' own box, a sample a rounding error
  // inside its far side is mapped one cell past the grid (vcglib 2020.09 reads out of bounds
  // and crashed on the 4.8 M-face Loop bunny).
  vcg::Box3f box = target.bbox;
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

} // namespace vrs_bench
