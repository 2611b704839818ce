#include "mesh/topology.h"

#include <algorithm>

#include "base/workers.h"

namespace vrs {

void Topology::build(const std::vector<uint32_t>& triangles, size_t vertex_count,
                     Workers* workers) {
  sibling_ = nullptr;
  // A range of vertices a thread: each reads every corner and writes only its own vertices'
  // counts and lists, in face order (the lists of one pass, whatever the threads). Scattered
  // writes are most of the time; the corners' reading is sequential.
  const size_t ranges = range_count(workers);
  auto range = [&](size_t r) { return range_of(r, ranges, vertex_count); };
  first_.resize(vertex_count);
  count_.resize(vertex_count);
  capacity_.resize(vertex_count);
  is_hub_.resize(vertex_count);
  std::vector<size_t> slots(ranges + 1, 0);
  for_each_range_on(workers, ranges, [&](size_t r) {
    const auto [lo, hi] = range(r);
    // Slack of 2 per vertex: after a removal a neighbour usually gains at most one or two
    // faces, so most slices never move.
    std::fill(capacity_.begin() + lo, capacity_.begin() + hi, 2u);
    std::fill(count_.begin() + lo, count_.begin() + hi, 0u);
    for (uint32_t c : triangles)
      if (c - lo < hi - lo) ++capacity_[c];
    for (size_t v = lo; v < hi; ++v)
      slots[r + 1] += capacity_[v];
  });
  for (size_t r = 0; r < ranges; ++r)
    slots[r + 1] += slots[r];
  pool_.reserve(slots[ranges] + slots[ranges] / 4);
  pool_.resize(slots[ranges]);
  for_each_range_on(workers, ranges, [&](size_t r) {
    const auto [lo, hi] = range(r);
    size_t offset = slots[r];
    for (size_t v = lo; v < hi; ++v) {
      first_[v] = static_cast<uint32_t>(offset);
      offset += capacity_[v];
      is_hub_[v] = 0;
    }
    std::fill(pool_.begin() + slots[r], pool_.begin() + slots[r + 1], kNone);
    for (size_t i = 0; i < triangles.size(); ++i) {
      const uint32_t v = triangles[i];
      if (v - lo < hi - lo) pool_[first_[v] + count_[v]++] = static_cast<uint32_t>(i / 3);
    }
  });
  hubs_.clear();
  for (uint32_t v = 0; v < vertex_count; ++v)
    if (count_[v] > kHubFaces) {
      is_hub_[v] = 1;
      hubs_.push_back({v, {}});
      Hub& h = hubs_.back();
      h.at.reserve(count_[v]);
      for (uint32_t i = 0; i < count_[v]; ++i)
        h.at[pool_[first_[v] + i]] = i;
    }
}

void Topology::grow(uint32_t v) {
  // Move the slice to the end of the pool with double room; the old slice is abandoned.
  uint32_t cap = capacity_[v] * 2 + 2;
  size_t at = pool_.size();
  pool_.resize(at + cap, kNone);
  std::copy_n(pool_.begin() + first_[v], count_[v], pool_.begin() + at);
  first_[v] = static_cast<uint32_t>(at);
  capacity_[v] = cap;
}

std::vector<Topology::Arena> Topology::reserve_arenas(const std::vector<size_t>& sizes) {
  std::vector<Arena> arenas(sizes.size());
  size_t at = pool_.size();
  for (size_t i = 0; i < sizes.size(); ++i) {
    arenas[i] = {at, at + sizes[i]};
    at += sizes[i];
  }
  pool_.resize(at, kNone);
  return arenas;
}

void Topology::add_face(uint32_t v, uint32_t face, Arena& arena) {
  if (add_face_in_place(v, face)) return;
  const uint32_t cap = capacity_[v] * 2 + 2;
  std::copy_n(pool_.begin() + first_[v], count_[v], pool_.begin() + arena.next);
  first_[v] = static_cast<uint32_t>(arena.next);
  capacity_[v] = cap;
  arena.next += cap;
  add_face_in_place(v, face);
}

void Topology::add_face(uint32_t v, uint32_t face) {
  if (!add_face_in_place(v, face)) {
    grow(v);
    add_face_in_place(v, face);
  }
}

void Topology::remove_face(uint32_t v, uint32_t face) {
  uint32_t* s = pool_.data() + first_[v];
  uint32_t n = count_[v];
  if (is_hub_[v]) {
    Hub& h = hub(v);
    const auto it = h.at.find(face);
    if (it == h.at.end()) return;
    const uint32_t i = it->second;
    h.at.erase(it);
    if (i != n - 1) {
      s[i] = s[n - 1];
      h.at[s[i]] = i;
    }
    --count_[v];
    return;
  }
  for (uint32_t i = 0; i < n; ++i) {
    if (s[i] == face) {
      // Keep the order: rings are built from it and the output must be deterministic.
      std::copy(s + i + 1, s + n, s + i);
      --count_[v];
      return;
    }
  }
}

VertexKind Topology::ring(uint32_t v, const uint32_t* tris, int max_valence, Ring& out) const {
  const uint32_t m = count_[v];
  out.verts = out.faces = 0;
  if (m == 0) return VertexKind::Isolated;
  if (m > static_cast<uint32_t>(std::min(max_valence, kMaxRing))) return VertexKind::HighValence;

  // Each face (v, a, b) contributes the directed ring edge a -> b.
  std::array<uint32_t, kMaxRing> from, to;
  const uint32_t* s = faces_of(v);
  for (uint32_t i = 0; i < m; ++i) {
    const uint32_t* t = tris + 3 * s[i];
    int c = t[0] == v ? 0 : t[1] == v ? 1 : 2;
    from[i] = t[(c + 1) % 3];
    to[i] = t[(c + 2) % 3];
  }
  // One pass over the pairs: a neighbour twice on the same side means an edge with > 2 faces
  // or flipped orientation; `next[j]` is the face that continues face j around v.
  std::array<uint32_t, kMaxRing> next;
  std::array<bool, kMaxRing> has_pred{};
  for (uint32_t i = 0; i < m; ++i)
    next[i] = kNone;
  for (uint32_t i = 0; i < m; ++i) {
    for (uint32_t j = i + 1; j < m; ++j) {
      if (from[j] == from[i] || to[j] == to[i]) return VertexKind::NonManifold;
      if (to[i] == from[j]) next[i] = j, has_pred[j] = true;
      if (to[j] == from[i]) next[j] = i, has_pred[i] = true;
    }
  }
  int start = -1, starts = 0;
  for (uint32_t i = 0; i < m; ++i)
    if (!has_pred[i]) start = static_cast<int>(i), ++starts;
  if (starts > 1) return VertexKind::NonManifold; // several fans meet at v
  const bool closed = starts == 0;
  uint32_t cur = closed ? 0 : static_cast<uint32_t>(start);
  for (uint32_t step = 0; step < m; ++step) {
    out.v[step] = from[cur];
    out.f[step] = s[cur];
    if (step + 1 == m) {
      if (closed ? next[cur] != 0 : next[cur] != kNone) return VertexKind::NonManifold;
      if (!closed) out.v[m] = to[cur];
    } else if (next[cur] == kNone || (closed && next[cur] == 0)) {
      return VertexKind::NonManifold; // the walk ended early: two fans share v
    }
    cur = next[cur];
  }
  out.faces = static_cast<int>(m);
  out.verts = static_cast<int>(closed ? m : m + 1);
  if (closed) return VertexKind::Interior;
  return m == 1 ? VertexKind::Corner : VertexKind::Boundary;
}

bool Topology::has_edge(uint32_t a, uint32_t b, const uint32_t* tris) const {
  if (!siblings()) return listed_edge(a, b, tris);
  // Copies of one vertex (fan_split.h) are one vertex on output: an edge from any copy of a to
  // any copy of b is (a, b), and a copy to another would be a face's two corners at one place.
  if (same_vertex(a, b)) return true;
  const auto& next = *sibling_;
  for (uint32_t x = a;;) {
    for (uint32_t y = b;;) {
      if (listed_edge(x, y, tris)) return true;
      if ((y = next[y]) == kNone || y == b) break;
    }
    if ((x = next[x]) == kNone || x == a) return false;
  }
}

bool Topology::listed_edge(uint32_t a, uint32_t b, const uint32_t* tris) const {
  if (count_[b] < count_[a]) std::swap(a, b);
  // Between two hubs the answer is "yes" unasked: every plan next to them would scan a hub's
  // whole list (a double cone of valence 100 000: quadratic), and the callers only ever refuse
  // a new edge that exists, so a hub-to-hub diagonal is refused, never made.
  if (count_[a] > kHubFaces) return true;
  const uint32_t* s = faces_of(a);
  for (uint32_t i = 0; i < count_[a]; ++i) {
    const uint32_t* t = tris + 3 * s[i];
    if (t[0] == b || t[1] == b || t[2] == b) return true;
  }
  return false;
}

int Topology::edge_faces(uint32_t a, uint32_t b, const uint32_t* tris) const {
  if (count_[b] < count_[a]) std::swap(a, b);
  const uint32_t* s = faces_of(a);
  int n = 0;
  for (uint32_t i = 0; i < count_[a]; ++i) {
    const uint32_t* t = tris + 3 * s[i];
    n += t[0] == b || t[1] == b || t[2] == b;
  }
  return n;
}

bool Topology::has_triangle(uint32_t a, uint32_t b, uint32_t c, const uint32_t* tris) const {
  // Through the corner of fewest faces: a hub of 100 000 faces is scanned by nobody.
  if (count_[b] < count_[a]) std::swap(a, b);
  if (count_[c] < count_[a]) std::swap(a, c);
  const uint32_t* s = faces_of(a);
  for (uint32_t i = 0; i < count_[a]; ++i) {
    const uint32_t* t = tris + 3 * s[i];
    bool hb = t[0] == b || t[1] == b || t[2] == b;
    bool hc = t[0] == c || t[1] == c || t[2] == c;
    if (hb && hc) return true;
  }
  return false;
}

} // namespace vrs
