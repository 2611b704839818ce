// Vertex -> triangle adjacency that follows removals, and the ordered ring of a vertex.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "base/uninitialized.h"

namespace vrs {

class Workers;

constexpr uint32_t kNone = 0xffffffffu;
// Hard cap of the ring buffers (stack arrays, so the main loop never allocates).
constexpr int kMaxRing = 64;

enum class VertexKind : uint8_t {
  Interior,    // closed manifold fan: removable
  Boundary,    // one open manifold fan of >= 2 triangles: removable on request
  Corner,      // one triangle only: always kept (removing it deletes the face)
  NonManifold, // several fans, an edge with > 2 faces, or inconsistent orientation: kept
  HighValence, // more neighbours than the cap: kept
  Isolated,    // no triangle
};

// The neighbours of a vertex in counter-clockwise order (as the triangles are oriented) and the
// triangle between verts[i] and verts[i+1]. Closed (interior): faces == verts. Open (boundary):
// verts == faces + 1, verts.front() and verts.back() are the boundary neighbours.
struct Ring {
  int verts = 0;
  int faces = 0;
  std::array<uint32_t, kMaxRing + 1> v;
  std::array<uint32_t, kMaxRing> f;
  bool closed() const { return verts == faces; }
};

// x mod k for 0 <= x < 2k: ring positions go round without a division (an integer division
// is tens of cycles, and the planning's inner loops took one per triangle).
inline int wrap(int x, int k) {
  return x < k ? x : x - k;
}

inline void prefetch(const void* p) {
#if defined(__GNUC__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

// Vertices of more faces are hubs: has_edge() answers "yes" between two of them unasked.
constexpr uint32_t kHubFaces = 1024;

class Topology {
 public:
  // `triangles` must hold valid indices with three distinct corners each; it is read, not kept.
  // Each list holds its faces in increasing order, whatever the workers.
  void build(const std::vector<uint32_t>& triangles, size_t vertex_count,
             Workers* workers = nullptr);

  uint32_t valence(uint32_t v) const { return count_[v]; } // number of incident triangles
  size_t vertex_count() const { return count_.size(); }
  const uint32_t* faces_of(uint32_t v) const { return pool_.data() + first_[v]; }

  void add_face(uint32_t v, uint32_t face);
  // Room at the pool's end that one part of the mesh grows its lists into while other parts
  // grow theirs (simplification by parts): no slice moves into another's, the pool never
  // reallocates under the threads.
  struct Arena {
    size_t next = 0, end = 0;
  };
  // Extends the pool by `sizes[i]` slots for each part i (one thread, before the parts run).
  std::vector<Arena> reserve_arenas(const std::vector<size_t>& sizes);
  // Slots v's list takes from an arena to hold `count` faces (0 when it has room).
  size_t growth(uint32_t v, size_t count) const {
    size_t slots = 0;
    for (size_t cap = capacity_[v]; count > cap; slots += cap)
      cap = 2 * cap + 2;
    return slots;
  }
  // add_face growing v's list inside `arena`; the caller made sure growth() fits.
  void add_face(uint32_t v, uint32_t face, Arena& arena);
  // add_face when v's slice has room (false: nothing done). Never moves memory, so threads may
  // call it on distinct vertices at once.
  bool add_face_in_place(uint32_t v, uint32_t face) {
    if (count_[v] == capacity_[v]) return false;
    if (is_hub_[v]) hub(v).at[face] = count_[v];
    pool_[first_[v] + count_[v]++] = face;
    return true;
  }
  void remove_face(uint32_t v, uint32_t face);
  void clear(uint32_t v) {
    count_[v] = 0;
    if (is_hub_[v]) hub(v).at.clear();
  }

  // Orders the fan of v; `tris` is the live triangle array. Rings longer than max_valence
  // (<= kMaxRing) are not built and the vertex is reported HighValence.
  VertexKind ring(uint32_t v, const uint32_t* tris, int max_valence, Ring& out) const;

  // Memory hints for a vertex about to be planned: its list's place, then its faces.
  void prefetch_list(uint32_t v) const {
    prefetch(&first_[v]);
    prefetch(&count_[v]);
  }
  void prefetch_faces(uint32_t v, const uint32_t* tris) const {
    // A ring's worth at most: a hub's 100 000 faces, asked for at every plan next to it, made
    // a double cone quadratic.
    const uint32_t* s = faces_of(v);
    const uint32_t n = std::min<uint32_t>(count_[v], kMaxRing);
    for (uint32_t i = 0; i < n; ++i)
      prefetch(tris + 3 * s[i]);
  }

  // Whether (a, b) is an edge; between two hubs (kHubFaces) "yes" without a look (callers only
  // refuse to make an edge that exists). With siblings, whether it is one on output.
  bool has_edge(uint32_t a, uint32_t b, const uint32_t* tris) const;
  // Vertices split for the run that are one on output (FanSplit::sibling, kept by the caller:
  // per vertex the next of its group, cyclic, kNone alone; null or empty: none).
  void set_siblings(const std::vector<uint32_t>* sibling) { sibling_ = sibling; }
  // Whether a and b are copies of one vertex (siblings).
  bool same_vertex(uint32_t a, uint32_t b) const {
    if (!siblings()) return a == b;
    for (uint32_t x = a;;) {
      if (x == b) return true;
      if ((x = (*sibling_)[x]) == kNone || x == a) return false;
    }
  }
  int edge_faces(uint32_t a, uint32_t b, const uint32_t* tris) const; // faces holding edge (a, b)
  bool has_triangle(uint32_t a, uint32_t b, uint32_t c, const uint32_t* tris) const;

 private:
  void grow(uint32_t v);
  bool listed_edge(uint32_t a, uint32_t b, const uint32_t* tris) const; // in their own lists
  bool siblings() const { return sibling_ && !sibling_->empty(); }

  // A hub's faces by their place in its list: removing one is O(1) (the last takes its
  // place) where a scan made a fan of 200 000 faces quadratic (2.8 s). Built for the vertices
  // that are hubs at build(); each is touched by one thread at a time (a hub is in the ring of
  // every removal next to it, so those are never planned together).
  struct Hub {
    uint32_t v;
    std::unordered_map<uint32_t, uint32_t> at;
  };
  Hub& hub(uint32_t v) {
    return *std::lower_bound(hubs_.begin(), hubs_.end(), v,
                             [](const Hub& h, uint32_t x) { return h.v < x; });
  }

  UninitVector<uint32_t> pool_; // per-vertex slices of triangle ids, with slack
  UninitVector<uint32_t> first_, count_, capacity_;
  UninitVector<uint8_t> is_hub_;
  std::vector<Hub> hubs_; // sorted by vertex
  const std::vector<uint32_t>* sibling_ = nullptr;
};

} // namespace vrs
