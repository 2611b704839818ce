#include "mesh/orientation.h"

#include <algorithm>
#include <utility>

namespace vrs {

namespace {

// The one other face holding the edge (a, b), or kNone when the edge has one face or more
// than two; `same` tells whether that face walks it a -> b too.
uint32_t across(uint32_t f, uint32_t a, uint32_t b, const uint32_t* t, const Topology& topo,
                bool& same) {
  uint32_t other = kNone;
  // Through the end of fewer faces: next to a hub of 100 000 faces, an edge costs its rim
  // vertex's few, not the hub's all (a double cone took 5 s, quadratic).
  const uint32_t s = topo.valence(b) < topo.valence(a) ? b : a;
  const uint32_t* faces = topo.faces_of(s);
  for (uint32_t i = 0; i < topo.valence(s); ++i) {
    const uint32_t g = faces[i];
    if (g == f) continue;
    int ia = -1, ib = -1;
    for (int c = 0; c < 3; ++c) {
      if (t[3 * g + c] == a) ia = c;
      if (t[3 * g + c] == b) ib = c;
    }
    if (ia < 0 || ib < 0) continue;
    if (other != kNone) return kNone; // a third face: not a manifold edge
    other = g;
    same = ib == (ia + 1) % 3; // a comes just before b in g
  }
  return other;
}

// Repeated directed edges (a -> b walked by more than one face, the count the input is judged
// by) on the edges [begin, end) (a << 32 | b, a < b), each face walking as given or reversed
// as `reversed(g)` says.
template <class Reversed>
size_t repeats_on(const uint64_t* begin, const uint64_t* end, const uint32_t* t,
                  const Topology& topo, Reversed reversed) {
  size_t repeats = 0;
  std::vector<uint32_t> holders;
  for (const uint64_t* e = begin; e != end; ++e) {
    const uint32_t a = uint32_t(*e >> 32), b = uint32_t(*e);
    holders.assign(topo.faces_of(a), topo.faces_of(a) + topo.valence(a));
    std::sort(holders.begin(), holders.end());
    holders.erase(std::unique(holders.begin(), holders.end()), holders.end());
    size_t ab = 0, ba = 0;
    for (uint32_t g : holders)
      for (int c = 0; c < 3; ++c) {
        uint32_t x = t[3 * g + c], y = t[3 * g + (c + 1) % 3];
        if (reversed(g)) std::swap(x, y);
        ab += x == a && y == b;
        ba += x == b && y == a;
      }
    repeats += (ab > 1 ? ab - 1 : 0) + (ba > 1 ? ba - 1 : 0);
  }
  return repeats;
}

} // namespace

size_t orient_coherently(std::vector<uint32_t>& tris, const Topology& topo, const uint32_t* rank,
                         std::vector<uint8_t>& flipped, Workers* workers) {
  const size_t faces = tris.size() / 3;
  const uint32_t* t = tris.data();
  // A cheap look first: does any manifold edge have its two faces walk it the same way? Both
  // then leave its first vertex a towards b, so a's faces name b twice as the corner after a:
  // per vertex, the successors compared (sorted at a hub), a repeat confirmed as a manifold
  // edge. (Asking only the faces that walk an edge from its lower vertex missed those whose
  // faces both walk it the other way.) In blocks on the workers.
  const size_t n = topo.vertex_count();
  constexpr size_t kBlock = 16384;
  constexpr uint32_t kFew = 16; // pairs compared up to this many faces, sorted beyond
  const size_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<uint8_t> incoherent(blocks, 0);
  auto look = [&](size_t block) {
    bool same = false;
    std::vector<uint64_t> hub; // (successor, face) of a vertex with many faces
    for (size_t v = block * kBlock; v < std::min(n, (block + 1) * kBlock); ++v) {
      const uint32_t a = uint32_t(v), m = topo.valence(a);
      const uint32_t* faces = topo.faces_of(a);
      auto next = [&](uint32_t f) {
        const uint32_t* c = t + 3 * size_t(f);
        return c[0] == a ? c[1] : c[1] == a ? c[2] : c[0];
      };
      auto walked_twice = [&](uint32_t f, uint32_t b) {
        return across(f, a, b, t, topo, same) != kNone && same;
      };
      if (m <= kFew) {
        std::array<uint32_t, kFew> succ;
        for (uint32_t i = 0; i < m; ++i)
          succ[i] = next(faces[i]);
        for (uint32_t i = 0; i < m; ++i)
          for (uint32_t j = i + 1; j < m; ++j)
            if (succ[i] == succ[j] && walked_twice(faces[i], succ[i])) {
              incoherent[block] = 1;
              return;
            }
        continue;
      }
      hub.clear();
      for (uint32_t i = 0; i < m; ++i)
        hub.push_back(uint64_t(next(faces[i])) << 32 | faces[i]);
      std::sort(hub.begin(), hub.end());
      for (size_t i = 1; i < hub.size(); ++i)
        if (hub[i] >> 32 == hub[i - 1] >> 32 &&
            walked_twice(uint32_t(hub[i]), uint32_t(hub[i] >> 32))) {
          incoherent[block] = 1;
          return;
        }
    }
  };
  for_each_on(workers, blocks, look);
  if (std::find(incoherent.begin(), incoherent.end(), 1) == incoherent.end()) return 0;
  bool same = false;

  // Breadth-first over manifold edges: a face's reversal follows from its neighbour's. Each
  // piece's faces are a range of `order`, with its edges not held by exactly two faces.
  struct Piece {
    size_t begin = 0, end = 0, edges_begin = 0, edges_end = 0;
    size_t reversed = 0, linked_same = 0; // linked edges walked the same way, seen from both
    uint32_t first = kNone;               // the face of lowest rank
    bool conflict = false;
  };
  constexpr uint8_t kUnseen = 2;
  std::vector<uint8_t> flip(faces, kUnseen);
  std::vector<uint32_t> order, piece_of(faces, kNone);
  std::vector<uint64_t> unlinked;
  std::vector<Piece> pieces;
  for (size_t seed = 0; seed < faces; ++seed) {
    if (flip[seed] != kUnseen) continue;
    Piece p;
    p.begin = order.size();
    p.edges_begin = unlinked.size();
    p.first = uint32_t(seed);
    order.push_back(uint32_t(seed));
    flip[seed] = 0;
    for (size_t next = p.begin; next < order.size(); ++next) {
      const uint32_t f = order[next];
      piece_of[f] = uint32_t(pieces.size());
      p.reversed += flip[f];
      if (rank[f] < rank[p.first]) p.first = f;
      for (int e = 0; e < 3; ++e) {
        const uint32_t a = t[3 * f + e], b = t[3 * f + (e + 1) % 3];
        const uint32_t g = across(f, a, b, t, topo, same);
        if (g == kNone) {
          if (a != b) unlinked.push_back(uint64_t(std::min(a, b)) << 32 | std::max(a, b));
          continue;
        }
        p.linked_same += same;
        if (flip[g] != kUnseen) {
          p.conflict = p.conflict || flip[g] != (flip[f] ^ same);
          continue;
        }
        flip[g] = uint8_t(flip[f] ^ same);
        order.push_back(g);
      }
    }
    p.end = order.size();
    std::sort(unlinked.begin() + p.edges_begin, unlinked.end());
    unlinked.erase(std::unique(unlinked.begin() + p.edges_begin, unlinked.end()), unlinked.end());
    p.edges_end = unlinked.size();
    pieces.push_back(p);
  }

  // Each piece in the order of its lowest-ranked face (the caller's order, whatever the faces'
  // own). A piece coherent as given stays so, as does one that is not orientable (a Moebius
  // strip): no choice would be coherent, and its conflicting vertices are kept as non-manifold.
  // Where a piece meets other faces at edges held by three or more (duplicated faces, fins),
  // its two orientations may repeat directed edges there: the one repeating fewer wins (a tie:
  // the orientation most of its faces had, then its first face's), and the piece stays as
  // given if both repeat more than it did (pieces decided before as they were left, the others
  // as given), so the input's count of repeated directed edges never grows.
  std::vector<uint32_t> by_rank(pieces.size());
  for (size_t i = 0; i < pieces.size(); ++i)
    by_rank[i] = uint32_t(i);
  std::sort(by_rank.begin(), by_rank.end(),
            [&](uint32_t x, uint32_t y) { return rank[pieces[x].first] < rank[pieces[y].first]; });
  std::vector<uint8_t> decided(pieces.size(), 0);
  size_t total = 0;
  for (uint32_t i : by_rank) {
    const Piece& p = pieces[i];
    bool keep = p.conflict || p.reversed == 0, invert = false;
    if (!keep) {
      auto cost = [&](int mode) { // 0: as given, 1: as the search found, 2: the opposite
        return repeats_on(unlinked.data() + p.edges_begin, unlinked.data() + p.edges_end, t, topo,
                          [&](uint32_t g) {
                            if (piece_of[g] != i) return decided[piece_of[g]] && flip[g] == 1;
                            return mode != 0 && bool(flip[g] ^ (mode == 2));
                          });
      };
      // Linked edges repeat nothing once oriented; as given, those walked the same way do.
      const size_t given = cost(0) + p.linked_same / 2, found = cost(1), opposite = cost(2);
      const size_t n = p.end - p.begin;
      invert = opposite != found ? opposite < found
                                 : 2 * p.reversed > n || (2 * p.reversed == n && flip[p.first]);
      keep = std::min(found, opposite) > given;
    }
    for (size_t k = p.begin; k < p.end; ++k)
      flip[order[k]] = keep ? 0 : uint8_t(flip[order[k]] ^ invert);
    decided[i] = 1;
    if (!keep) total += invert ? p.end - p.begin - p.reversed : p.reversed;
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

TurnedByWelding turned_by_welding(const std::vector<uint32_t>& tris, const Topology& topo,
                                  const std::vector<uint8_t>& flipped, std::vector<uint32_t> apart,
                                  const uint32_t* rank, Workers* workers) {
  TurnedByWelding out;
  Topology apart_topo;
  apart_topo.build(apart, topo.vertex_count(), workers);
  std::vector<uint8_t> flipped_apart;
  orient_coherently(apart, apart_topo, rank, flipped_apart, workers);
  const size_t faces = tris.size() / 3;
  out.faces.assign(faces, 0);
  bool any = false;
  for (size_t f = 0; f < faces; ++f)
    any |= out.faces[f] =
        (!flipped.empty() && flipped[f]) != (!flipped_apart.empty() && flipped_apart[f]);
  if (!any) return TurnedByWelding{};
  const uint32_t* t = tris.data();
  for (size_t f = 0; f < faces; ++f) {
    if (!out.faces[f]) continue;
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = t[3 * f + c], b = t[3 * f + (c + 1) % 3];
      bool same = false;
      const uint32_t g = across(uint32_t(f), a, b, t, topo, same);
      if (g != kNone && !out.faces[g]) out.edges.insert(out.edges.end(), {a, b});
    }
  }
  return out;
}

} // namespace vrs
