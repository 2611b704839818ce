// Maps an evaluation factor to an interval of the hash table (paper §2.3).
#pragma once

#include <algorithm>
#include <cmath>

#include "vrs/simplify.h"

namespace vrs {

struct IntervalMap {
  int n = 2;
  IntervalMapping kind = IntervalMapping::Linear;
  double f_max = 0; // top of the range; factors >= the last interval's floor share the last one

  // Smallest factor the logarithmic mapping resolves, relative to f_max: six decades hold the
  // factors of a smooth scan and of a CAD mesh's flat regions alike.
  static constexpr double kLogDecades = 6.0;

  int interval_of(double f) const {
    if (!(f > 0) || !(f_max > 0)) return f > 0 ? n - 1 : 0;
    double x;
    if (kind == IntervalMapping::Linear) {
      x = f / f_max;
    } else {
      x = 1.0 + std::log10(f / f_max) / kLogDecades;
    }
    if (!(x > 0)) return 0;
    double i = x * n;
    return i >= n - 1 ? n - 1 : static_cast<int>(i);
  }
};

} // namespace vrs
