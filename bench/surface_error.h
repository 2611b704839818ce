// Symmetric surface error between two meshes, as MeshLab's "Hausdorff Distance" filter measures
// it: area-uniform (Monte Carlo) samples on one surface, the exact closest point on the other
// through vcglib's uniform grid, both directions. Distances relative to `a`'s bounding-box
// diagonal.
#pragma once

#include <cstddef>

#include "vrs/simplify.h"

namespace vrs_bench {

struct SurfaceError {
  double max = 0, mean = 0, rms = 0; // symmetric: max of both, mean and rms over all samples
  double diagonal = 0;               // of `a`, the unit of the relative values
  size_t samples = 0;
};

// `samples_per_side` area-uniform samples on each surface (plus its vertices).
SurfaceError surface_error(const vrs::Mesh& a, const vrs::Mesh& b, size_t samples_per_side);

// Fold-overs: the share of `simplified`'s area (area-uniform samples, fixed seed) whose face
// turns more than 90° from the `original` face nearest to the sample: the output facing against
// the surface it stands for. 0 for an untouched mesh.
double fold_over_share(const vrs::Mesh& original, const vrs::Mesh& simplified, size_t samples);

} // namespace vrs_bench
