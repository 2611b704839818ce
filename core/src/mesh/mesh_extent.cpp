// The mesh's size, the unit of relative errors, and its coordinates as the core holds them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "vrs/simplify.h"

namespace vrs {

double bounding_box_diagonal(const Mesh& mesh) {
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  const auto& p = mesh.positions;
  for (size_t i = 0; i + 2 < p.size(); i += 3) {
    if (!std::isfinite(p[i]) || !std::isfinite(p[i + 1]) || !std::isfinite(p[i + 2])) continue;
    for (int c = 0; c < 3; ++c)
      lo[c] = std::min(lo[c], double(p[i + c])), hi[c] = std::max(hi[c], double(p[i + c]));
  }
  if (!(hi[0] >= lo[0])) return 0.0;
  double d2 = 0;
  for (int c = 0; c < 3; ++c)
    d2 += (hi[c] - lo[c]) * (hi[c] - lo[c]);
  return std::sqrt(d2);
}

bool beyond_float(double x) {
  if (!std::isfinite(x) || double(float(x)) == x) return false;
  // A decimal of 7 significant digits or fewer is what a text file's float says: read as a
  // double it is not a float's value, yet a float stands for it.
  char text[32];
  std::snprintf(text, sizeof text, "%.7g", x);
  return std::strtod(text, nullptr) != x;
}

std::vector<float> float_positions(const double* xyz, size_t vertices) {
  std::vector<float> out(3 * vertices);
  bool beyond = false;
  for (size_t i = 0; i < 3 * vertices && !beyond; ++i)
    beyond = beyond_float(xyz[i]);
  double origin[3] = {0, 0, 0};
  if (beyond)
    for (size_t v = 0; v < vertices; ++v)
      if (std::isfinite(xyz[3 * v]) && std::isfinite(xyz[3 * v + 1]) &&
          std::isfinite(xyz[3 * v + 2])) {
        std::copy(xyz + 3 * v, xyz + 3 * v + 3, origin);
        break;
      }
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = float(xyz[i] - origin[i % 3]);
  return out;
}

} // namespace vrs
