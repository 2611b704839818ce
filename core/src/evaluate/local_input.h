// The input faces around a fan (those of its ring's vertices, its apex and the points its
// faces carry): the surface the fan stands for, which the slide (slide.cpp) asks instead of
// the whole input's hierarchy (whose build and questions cost more than the run itself on large
// meshes). A grid of the faces' spheres, read instead of every face, cut instructions but not
// the time.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "base/geometry.h"
#include "fill/triangulation.h"

namespace vrs {

struct LocalInput {
  int count = 0;
  std::vector<uint32_t> face; // numbers into InputSurface's faces
  std::vector<Vec3> a, b, c, n;
  std::vector<double> cx, cy, cz, radius; // each face's bounding sphere
  std::vector<double> d2, dc2, reach2;    // measure_against's, per point: to each face, its centre
  double mean_area = 0;
  std::vector<int> close; // measure_against's, per point: the faces that may be nearest

  // Sizes the per-face arrays for `faces` faces (count is then set by the caller).
  void resize(size_t faces);
};

// A fan against the input around it: an L x L grid of each triangle's points, each against
// its nearest local input face, by area (the mean distance times the area; past `stop` the
// rest is not measured). `folds`: some point turns from the input as InputSurface::turned_at
// judges it (its nearest face, or the sum of those as near: kAgreeAlone), as the benchmark
// counts a fold-over. `fine`: L grows
// with the input faces a triangle covers, as InputSurface::folds's grid. `farthest`: the
// largest squared distance met.
double measure_against(const Patch& patch, LocalInput& in, bool& folds,
                       double stop = std::numeric_limits<double>::infinity(), bool fine = false,
                       double* farthest = nullptr);

} // namespace vrs
