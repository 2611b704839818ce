// A fan measured against the input around it (local_input.h).
#include "evaluate/local_input.h"

#include <algorithm>
#include <cmath>

#include "base/distance.h"
#include "evaluate/input_surface.h"

namespace vrs {

namespace {
constexpr int kSlideGrid = 2; // a fan triangle's points against the input: L x L

// Per face: the squared distance from x to its centre, and the square of its radius plus
// `reach`; on unaliased arrays, so that the compiler makes it vector arithmetic.
void centre_distances(LocalInput& in, Vec3 x, double reach) {
  const double* __restrict cx = in.cx.data();
  const double* __restrict cy = in.cy.data();
  const double* __restrict cz = in.cz.data();
  const double* __restrict radius = in.radius.data();
  double* __restrict dc2 = in.dc2.data();
  double* __restrict reach2 = in.reach2.data();
  const int n = in.count;
  const double px = x.x, py = x.y, pz = x.z;
  for (int f = 0; f < n; ++f) {
    const double dx = px - cx[f], dy = py - cy[f], dz = pz - cz[f];
    dc2[f] = dx * dx + dy * dy + dz * dz;
    const double r = radius[f] + reach;
    reach2[f] = r * r;
  }
}
} // namespace

void LocalInput::resize(size_t faces) {
  for (auto* x : {&a, &b, &c, &n})
    x->resize(faces);
  close.resize(faces);
  for (auto* x : {&cx, &cy, &cz, &radius, &d2, &dc2, &reach2})
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
      // nearest: most often the nearest face, measured first it leaves few others. The
      // distances to every centre in a loop of their own (vector arithmetic), then the list
      // made without a branch (most faces are not on it): a slide's time is mostly here.
      centre_distances(in, x, reach);
      const double* reach2 = in.reach2.data();
      int* close = in.close.data();
      int closes = 0;
      for (int f = 0; f < in.count; ++f) {
        close[closes] = f;
        closes += dc2[f] <= reach2[f]; // within(f, reach)
      }
      int centred = hint;
      double centre2 = std::numeric_limits<double>::infinity();
      for (int i = 0; i < closes; ++i) {
        const int f = close[i];
        d2[f] = std::numeric_limits<double>::infinity();
        if (dc2[f] < centre2) centre2 = dc2[f], centred = f;
      }
      d2[hint] = best;
      if (centred != hint) {
        d2[centred] = point_triangle_distance2(x, in.a[centred], in.b[centred], in.c[centred]);
        if (d2[centred] < best) best = d2[centred], hint = centred;
      }
      double s = std::sqrt(best);
      for (const int* f_ = close; f_ != close + closes; ++f_) {
        const int f = *f_;
        if (d2[f] != std::numeric_limits<double>::infinity()) continue; // measured above
        if (within(f, s)) {
          d2[f] = point_triangle_distance2(x, in.a[f], in.b[f], in.c[f]);
          if (d2[f] < best) best = d2[f], hint = f, s = std::sqrt(best);
        }
      }
      out += w / (L * L) * s;
      if (farthest) *farthest = std::max(*farthest, best);
      // As InputSurface::turned_at asks (kAgreeAlone); nt is of length 2 w.
      InputSurface::TieVote vote(nt, 2 * w);
      bool agrees = vote.alone(in.n[hint]);
      if (!agrees) {
        const double tie = InputSurface::tie_reach2(best, x);
        const double tie_s = std::sqrt(tie);
        for (const int* f_ = close; f_ != close + closes && !agrees; ++f_) {
          const int f = *f_;
          if (!within(f, tie_s)) continue;
          if (d2[f] == std::numeric_limits<double>::infinity())
            d2[f] = point_triangle_distance2(x, in.a[f], in.b[f], in.c[f]);
          if (d2[f] > tie) continue;
          if (vote.alone(in.n[f]))
            agrees = true;
          else
            vote.add(in.n[f]);
        }
        agrees = agrees || vote.summed();
      }
      folds = folds || !agrees;
      return out > stop; // no better: the rest does not matter
    });
    if (stopped) return out;
  }
  return out;
}

} // namespace vrs
