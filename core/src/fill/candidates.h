// The ways to fill the hole a removed vertex leaves. Each candidate writes the triangles of a
// patch over the ring (indices into it); whether it is allowed is the vetoes' business
// (vetoes.h), what it costs the priority's. Kept apart so a new filling is one new function.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "fill/removal_types.h"
#include "fill/triangulation.h"
#include "mesh/topology.h"

namespace vrs {

// Candidate 0 is the paper's: the ring projected on the evaluated plane and triangulated
// there. Candidates 1..k are the fans from ring vertex apex = candidate - 1: exactly a
// half-edge collapse of the vertex onto that neighbour, which needs no projection (it still
// works where the ring folds on every plane: tips, creases, thin parts).
// A three-vertex ring has one triangle whatever the apex: one fan stands for all. A vertex of
// a single triangle (an open two-vertex ring) has one filling: none, the triangle goes.
inline int candidate_count(const Ring& ring, bool fans) {
  return fans && ring.verts > 2 ? 1 + (ring.verts == 3 ? 1 : ring.verts) : 1;
}

// The fan candidate whose triangles `patch` holds exactly as fill_triangles writes them (the
// projection of a convex ring is the fan of its best-shaped apex), or -1.
int fan_candidate(const Ring& ring, const Patch& patch);

// Writes candidate `c` into `out` (tri and from; the projection `out.p`, `out.q` and
// `out.normal` must be set). False when the projection folds (candidate 0 only).
bool fill_candidate(const Ring& ring, OpenRing open, int c, Patch& out);
// fill_candidate without `out.from`: what ranking the candidates reads (a twentieth of a plan's
// instructions were corner faces set for candidates never vetted).
bool fill_triangles(const Ring& ring, OpenRing open, int c, Patch& out);

// Rings of more neighbours than this get no least-cost filling (its work grows as k^3).
constexpr int kMaxLeastCostRing = 20;

// The least-cost filling: of every triangulation of the ring's polygon (closed by the chord
// when open), the one whose worst triangle costs least, ties broken by the sum. It needs no
// projection and reaches fillings no fan and no ear clipping makes: where each of those has a
// triangle a veto refuses, one without such a triangle is found if it exists.
// `cost(a, b, c)`: the triangle (a < b < c, ring positions) priced, +inf where vetoed;
// `diagonal_ok(a, b)`: whether the new edge may be made. False when no triangulation is allowed.
template <class Cost, class DiagonalOk>
bool fill_least_cost(const Ring& ring, Cost&& cost, DiagonalOk&& diagonal_ok, Patch& out) {
  const int k = ring.verts;
  if (k < 3 || k > kMaxLeastCostRing) return false;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr int K = kMaxLeastCostRing;
  // Two exact passes: the least worst triangle W first, then the least sum of triangles none
  // above W (the pair in one pass is not optimal: a part with a worse worst can still give
  // the least sum). cell[i][j] is about the sub-polygon i, i+1, ..., j (j - i >= 2) under the
  // edge (i, j); edges (i, i + 1) are ring edges and cost nothing.
  std::array<double, K * K * K> price; // each triangle priced once
  auto tri_price = [&](int i, int m, int j) -> double& { return price[(i * K + m) * K + j]; };
  std::array<std::array<double, K>, K> worst, sum;
  std::array<std::array<uint8_t, K>, K> split;
  auto part = [&](const std::array<std::array<double, K>, K>& cell, int i, int j) {
    return j - i >= 2 ? cell[i][j] : 0.0;
  };
  for (int len = 2; len < k; ++len)
    for (int i = 0; i + len < k; ++i) {
      const int j = i + len;
      double best = kInf;
      const bool allowed = len == k - 1 || diagonal_ok(i, j);
      for (int m = i + 1; m < j; ++m) {
        double& t = tri_price(i, m, j);
        t = allowed ? cost(i, m, j) : kInf;
        best = std::min(best, std::max({part(worst, i, m), part(worst, m, j), t}));
      }
      worst[i][j] = best;
    }
  const double bound = worst[0][k - 1];
  if (!(bound < kInf)) return false;
  for (int len = 2; len < k; ++len)
    for (int i = 0; i + len < k; ++i) {
      const int j = i + len;
      double best = kInf;
      uint8_t at = 0;
      for (int m = i + 1; m < j; ++m) {
        const double t = tri_price(i, m, j);
        if (!(t <= bound)) continue;
        const double total = part(sum, i, m) + part(sum, m, j) + t;
        if (total < best) best = total, at = uint8_t(m);
      }
      sum[i][j] = best;
      split[i][j] = at;
    }
  // Unwind the splits (an explicit stack: no recursion on the workers).
  out.count = 0;
  std::array<std::array<uint8_t, 2>, kMaxLeastCostRing> todo;
  int top = 0;
  todo[top++] = {0, uint8_t(k - 1)};
  while (top > 0) {
    const auto [i, j] = todo[--top];
    const uint8_t m = split[i][j];
    out.tri[out.count++] = {i, m, j};
    if (m - i >= 2) todo[top++] = {i, m};
    if (j - m >= 2) todo[top++] = {m, j};
  }
  return true;
}

// Sets `out.from` for its triangles (the ring face each new corner takes its data from).
void set_corner_faces(const Ring& ring, Patch& out);

} // namespace vrs
