#include "orientation.h"

#include <utility>

namespace vrs {

namespace {

// The one other face holding the edge (a, b), or kNone when the edge has one face or more
// than two; `same` tells whether that face walks it a -> b too.
uint32_t across(uint32_t f, uint32_t a, uint32_t b, const uint32_t* t, const Topology& topo,
                bool& same) {
  uint32_t other = kNone;
  const uint32_t* faces = topo.faces_of(a);
  for (uint32_t i = 0; i < topo.valence(a); ++i) {
    const uint32_t g = faces[i];
    if (g == f) continue;
    for (int c = 0; c < 3; ++c)
      if (t[3 * g + c] == b) {
        if (other != kNone) return kNone; // a third face: not a manifold edge
        other = g;
        same = t[3 * g + (c + 2) % 3] == a; // a comes just before b in g
      }
  }
  return other;
}

} // namespace

size_t orient_coherently(std::vector<uint32_t>& tris, const Topology& topo, const uint32_t* rank,
                         std::vector<uint8_t>& flipped) {
  const size_t faces = tris.size() / 3;
  const uint32_t* t = tris.data();
  // A cheap look first: does any manifold edge have its two faces walk it the same way? Such
  // an edge is walked a -> b by both, so looking from the faces where a < b finds it.
  bool coherent = true;
  bool same = false;
  for (size_t f = 0; f < faces && coherent; ++f)
    for (int e = 0; e < 3 && coherent; ++e) {
      const uint32_t a = t[3 * f + e], b = t[3 * f + (e + 1) % 3];
      if (a < b && across(uint32_t(f), a, b, t, topo, same) != kNone && same) coherent = false;
    }
  if (coherent) return 0;

  // Breadth-first over manifold edges: a face's reversal follows from its neighbour's.
  constexpr uint8_t kUnseen = 2;
  std::vector<uint8_t> flip(faces, kUnseen);
  std::vector<uint32_t> piece;
  size_t total = 0;
  for (size_t seed = 0; seed < faces; ++seed) {
    if (flip[seed] != kUnseen) continue;
    piece.clear();
    piece.push_back(uint32_t(seed));
    flip[seed] = 0;
    size_t reversed = 0;
    uint32_t first = uint32_t(seed);
    bool conflict = false;
    for (size_t next = 0; next < piece.size(); ++next) {
      const uint32_t f = piece[next];
      reversed += flip[f];
      if (rank[f] < rank[first]) first = f;
      for (int e = 0; e < 3; ++e) {
        const uint32_t g = across(f, t[3 * f + e], t[3 * f + (e + 1) % 3], t, topo, same);
        if (g == kNone) continue;
        if (flip[g] != kUnseen) {
          conflict = conflict || flip[g] != (flip[f] ^ same);
          continue;
        }
        flip[g] = uint8_t(flip[f] ^ same);
        piece.push_back(g);
      }
    }
    // A piece that is not orientable (a Moebius strip) stays as given: no choice would be
    // coherent, and its conflicting vertices are kept as non-manifold.
    const bool invert =
        2 * reversed > piece.size() || (2 * reversed == piece.size() && flip[first]);
    for (uint32_t f : piece)
      flip[f] = conflict ? 0 : uint8_t(flip[f] ^ invert);
    if (!conflict) total += invert ? piece.size() - reversed : reversed;
  }
  if (total == 0) return 0;
  flipped.assign(faces, 0);
  for (size_t f = 0; f < faces; ++f)
    if (flip[f]) {
      flipped[f] = 1;
      std::swap(tris[3 * f + 1], tris[3 * f + 2]);
    }
  return total;
}

} // namespace vrs
