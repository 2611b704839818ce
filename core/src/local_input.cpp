// A fan measured against the input around it (local_input.h).
#include "local_input.h"

#include <algorithm>
#include <cmath>

#include "input_surface.h"
#include "local_error.h"

namespace vrs {

namespace {
constexpr int kSlideGrid = 2; // a fan triangle's points against the input: L x L
} // namespace

void LocalInput::resize(size_t faces) {
  for (auto* x : {&a, &b, &c, &n})
    x->resize(faces);
  for (auto* x : {&cx, &cy, &cz, &radius, &d2, &dc2})
    x->resize(faces);
}

double measure_against(const Patch& patch, LocalInput& in, bool& folds, double stop, bool fine,
                       double* farthest) {
  double out = 0;
  folds = false;
  int hint = 0;
  for (int t = 0; t < patch.count; ++t) {
    const auto& tri = patch.tri[t];
    const Vec3 a = patch.q[tri[0]], b = patch.q[tri[1]], c = patch.q[tri[2]];
    const Vec3 nt = cross(b - a, c - a);
    const double w = 0.5 * length(nt);
    const int L = fine ? InputSurface::grid_side(w / in.mean_area) : kSlideGrid;
    const bool stopped = each_grid_point(a, b, c, L, [&](Vec3 x) {
      // The last point's nearest face bounds the search at once: only faces whose
      // bounding sphere comes within that distance (and a tie's slack) are read.
      double best = point_triangle_distance2(x, in.a[hint], in.b[hint], in.c[hint]);
      const double reach = std::sqrt(InputSurface::tie_reach2(best, x));
      double* d2 = in.d2.data();
      double* dc2 = in.dc2.data();
      // A face can be nearer than s only if its centre is within its radius + s.
      auto within = [&](int f, double s) {
        const double r = in.radius[f] + s;
        return dc2[f] <= r * r;
      };
      // The faces that may be nearest or tie with it (within the last point's nearest
      // face's reach, which only shrinks), and among them the one whose centre is
      // nearest: most often the nearest face, measured first it leaves few others.
      std::vector<int>& close = in.close;
      close.clear();
      int centred = hint;
      double centre2 = std::numeric_limits<double>::infinity();
      for (int f = 0; f < in.count; ++f) {
        const double dx = x.x - in.cx[f], dy = x.y - in.cy[f], dz = x.z - in.cz[f];
        dc2[f] = dx * dx + dy * dy + dz * dz;
        if (!within(f, reach)) continue;
        close.push_back(f);
        d2[f] = std::numeric_limits<double>::infinity();
        if (dc2[f] < centre2) centre2 = dc2[f], centred = f;
      }
      d2[hint] = best;
      if (centred != hint) {
        d2[centred] = point_triangle_distance2(x, in.a[centred], in.b[centred], in.c[centred]);
        if (d2[centred] < best) best = d2[centred], hint = centred;
      }
      double s = std::sqrt(best);
      for (int f : close) {
        if (d2[f] != std::numeric_limits<double>::infinity()) continue; // measured above
        if (within(f, s)) {
          d2[f] = point_triangle_distance2(x, in.a[f], in.b[f], in.c[f]);
          if (d2[f] < best) best = d2[f], hint = f, s = std::sqrt(best);
        }
      }
      out += w / (L * L) * s;
      if (farthest) *farthest = std::max(*farthest, best);
      const double tie = InputSurface::tie_reach2(best, x);
      const double tie_s = std::sqrt(tie);
      bool agrees = false;
      for (int f : close) {
        if (!within(f, tie_s)) continue;
        if (d2[f] == std::numeric_limits<double>::infinity())
          d2[f] = point_triangle_distance2(x, in.a[f], in.b[f], in.c[f]);
        if (d2[f] <= tie && dot(in.n[f], nt) > 0) {
          agrees = true;
          break;
        }
      }
      folds = folds || !agrees;
      return out > stop; // no better: the rest does not matter
    });
    if (stopped) return out;
  }
  return out;
}

} // namespace vrs
