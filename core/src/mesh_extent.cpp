// The mesh's size, the unit of relative errors.
#include <algorithm>
#include <cmath>

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

} // namespace vrs
