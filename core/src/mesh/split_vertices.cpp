#include "mesh/split_vertices.h"

#include <algorithm>
#include <cstring>

#include "base/workers.h"
#include "mesh/topology.h"
#include "vrs/simplify.h"

namespace vrs {

namespace {

struct Sets { // union-find, the lowest index standing for its set
  std::vector<uint32_t> parent;
  explicit Sets(size_t n) : parent(n) {
    for (size_t v = 0; v < n; ++v)
      parent[v] = uint32_t(v);
  }
  uint32_t find(uint32_t v) {
    while (parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  }
  void join(uint32_t a, uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

uint64_t edge_key(uint32_t a, uint32_t b) {
  return uint64_t(std::min(a, b)) << 32 | std::max(a, b);
}

// Sorts `v` by its `key` and calls `run(i, j)` for each run [i, j) of one key.
template <class T, class Run> void sorted_runs(std::vector<T>& v, Run run) {
  std::sort(v.begin(), v.end(), [](const T& x, const T& y) { return x.key < y.key; });
  for (size_t i = 0, j; i < v.size(); i = j) {
    for (j = i; j < v.size() && v[j].key == v[i].key;)
      ++j;
    run(i, j);
  }
}

uint64_t position_hash(const float* p) {
  uint32_t bits[3];
  std::memcpy(bits, p, sizeof bits);
  uint64_t h = (bits[0] * 0x9E3779B97F4A7C15ull) ^ (bits[1] * 0xC2B2AE3D27D4EB4Full) ^
               (bits[2] * 0x165667B19E3779F9ull);
  return h ^ h >> 29;
}

// For each referenced vertex, the first referenced vertex at the same position, bit for bit
// (kNone: unreferenced); false when no two share one. A thread a group of positions (by their
// hash's top bits), each with its own table filled in vertex order: the classes of one pass.
bool position_classes(const std::vector<uint32_t>& tris, const std::vector<float>& pos,
                      UninitVector<uint32_t>& cls, Workers* workers) {
  const size_t n = pos.size() / 3;
  const size_t groups = range_count(workers);
  cls.resize(n);
  // Referenced vertices: a range of vertices a thread, each reading every corner.
  for_each_range_on(workers, groups, [&](size_t g) {
    const auto [lo, hi] = range_of(g, groups, n);
    std::fill(cls.begin() + lo, cls.begin() + hi, kNone);
    for (uint32_t v : tris)
      if (v - lo < hi - lo) cls[v] = v;
  });
  auto group_of = [groups](uint64_t h) { return size_t((h >> 40) % groups); };
  // Each group's finds are kept apart and written after: every group reads every vertex's
  // entry (referenced or not) while the others search.
  std::vector<std::vector<std::pair<uint32_t, uint32_t>>> same(groups);
  for_each_range_on(workers, groups, [&](size_t g) {
    size_t members = 0;
    for (uint32_t v = 0; v < n; ++v)
      members += cls[v] != kNone && group_of(position_hash(&pos[3 * size_t(v)])) == g;
    size_t cap = 16;
    while (cap < 2 * members)
      cap <<= 1;
    std::vector<uint32_t> table(cap, kNone); // open addressing, linear probing
    for (uint32_t v = 0; v < n; ++v) {
      if (cls[v] == kNone) continue;
      const uint64_t h = position_hash(&pos[3 * size_t(v)]);
      if (group_of(h) != g) continue;
      for (size_t s = h & (cap - 1);; s = (s + 1) & (cap - 1)) {
        const uint32_t u = table[s];
        if (u == kNone) {
          table[s] = v;
          break;
        }
        if (std::memcmp(&pos[3 * size_t(u)], &pos[3 * size_t(v)], 3 * sizeof(float)) == 0) {
          same[g].push_back({v, u});
          break;
        }
      }
    }
  });
  for_each_range_on(workers, groups, [&](size_t g) {
    for (const auto& [v, u] : same[g])
      cls[v] = u;
  });
  return std::any_of(same.begin(), same.end(), [](const auto& s) { return !s.empty(); });
}

} // namespace

Welding weld_split_vertices(std::vector<uint32_t>& tris, const std::vector<float>& positions,
                            Workers* workers) {
  Welding w;
  UninitVector<uint32_t> cls;
  if (!position_classes(tris, positions, cls, workers)) return w;
  const size_t n = cls.size();
  std::vector<uint32_t> copies(n, 0);
  for (size_t v = 0; v < n; ++v)
    if (cls[v] != kNone) ++copies[cls[v]];
  auto split = [&](uint32_t v) { return copies[cls[v]] > 1; };

  // The border edges between split vertices: edges of those held by one face only.
  struct Edge {
    uint64_t key;
    uint32_t a, b;
  };
  auto repeats = [&](size_t i) { // a face dropped later (prepare)
    return tris[i] == tris[i + 1] || tris[i + 1] == tris[i + 2] || tris[i + 2] == tris[i];
  };
  std::vector<Edge> edges;
  for (size_t i = 0; i + 2 < tris.size(); i += 3)
    for (int c = 0; c < 3 && !repeats(i); ++c) {
      const uint32_t a = tris[i + c], b = tris[i + (c + 1) % 3];
      if (split(a) && split(b)) edges.push_back({edge_key(a, b), a, b});
    }
  std::vector<Edge> border;
  sorted_runs(edges, [&](size_t i, size_t j) {
    const Edge& e = edges[i];
    if (j == i + 1 && cls[e.a] != cls[e.b])
      border.push_back({edge_key(cls[e.a], cls[e.b]), e.a, e.b});
  });
  std::vector<Edge>().swap(edges);

  // Two border edges at the same two positions, and no third: one edge of the surface.
  // Walked the opposite ways, as by two faces of one oriented surface, or the same way: panels
  // written in different orientations (a CAD export's, CGAL's boeing), turned to agree for the
  // run (orientation.h) and given back their own on output. Left apart, every border vertex
  // there is a twin, kept, and the interior alone paid for the target.
  Sets sets(n);
  sorted_runs(border, [&](size_t i, size_t j) {
    if (j != i + 2) return;
    const Edge &e = border[i], &f = border[i + 1];
    const bool opposite = cls[e.a] == cls[f.b];
    sets.join(e.a, opposite ? f.b : f.a);
    sets.join(e.b, opposite ? f.a : f.b);
  });
  std::vector<Edge>().swap(border);

  // A face that would hold one vertex twice (a sliver along the seam), or an edge that
  // welding would give a third face (sets joined through other edges), keeps its copies
  // apart: those sets are undone, until no such face or edge is left.
  struct Walk {
    uint64_t key;            // the welded edge, either way
    uint32_t from, to, a, b; // welded ends as walked; the input's ends
  };
  std::vector<Walk> walks;
  for (bool again = true; again;) {
    again = false;
    std::vector<uint8_t> undo(n, 0);
    std::vector<uint32_t> size(n, 0);
    for (uint32_t v = 0; v < n; ++v)
      ++size[sets.find(v)];
    walks.clear();
    for (size_t i = 0; i + 2 < tris.size(); i += 3) {
      const uint32_t *t = &tris[i], a = sets.find(t[0]), b = sets.find(t[1]), c = sets.find(t[2]);
      if (repeats(i)) continue;
      if (a == b || b == c || c == a) {
        for (uint32_t r : {a, b, c})
          undo[r] = 1;
        again = true;
        continue;
      }
      const uint32_t r[3] = {a, b, c};
      for (int k = 0; k < 3; ++k)
        if (size[r[k]] > 1 || size[r[(k + 1) % 3]] > 1)
          walks.push_back(
              {edge_key(r[k], r[(k + 1) % 3]), r[k], r[(k + 1) % 3], t[k], t[(k + 1) % 3]});
    }
    size_t same_way = 0; // welded edges walked the same way (the input's own such edges aside)
    sorted_runs(walks, [&](size_t i, size_t j) {
      if (j - i > 2) {
        undo[walks[i].from] = undo[walks[i].to] = 1;
        again = true;
      }
      same_way += j == i + 2 && walks[i].from == walks[i + 1].from &&
                  (walks[i].a != walks[i + 1].a || walks[i].b != walks[i + 1].b);
    });
    if (!again) {
      w.same_way = same_way;
      break;
    }
    std::vector<uint32_t> root(n);
    for (uint32_t v = 0; v < n; ++v)
      root[v] = sets.find(v);
    for (uint32_t v = 0; v < n; ++v)
      if (undo[root[v]]) sets.parent[v] = v;
  }

  w.rep.resize(n);
  for (uint32_t v = 0; v < n; ++v) {
    w.rep[v] = sets.find(v);
    w.welded += w.rep[v] != v;
  }
  if (w.welded == 0) return Welding{};
  w.corners = tris;
  std::vector<uint32_t> members(n, 0);
  for (uint32_t v = 0; v < n; ++v)
    ++members[w.rep[v]];
  for (uint32_t& v : tris)
    v = w.rep[v];

  // The seams: welded edges whose two faces hold different copies at an end.
  struct Side {
    uint64_t key;
    uint32_t lo, hi; // the copies at the lower and the higher standing end
  };
  std::vector<Side> sides;
  for (size_t i = 0; i + 2 < tris.size(); i += 3)
    for (int c = 0; c < 3 && !repeats(i); ++c) {
      const uint32_t a = tris[i + c], b = tris[i + (c + 1) % 3];
      if (members[a] < 2 && members[b] < 2) continue; // a seam may end at a shared vertex
      const uint32_t ca = w.corners[i + c], cb = w.corners[i + (c + 1) % 3];
      sides.push_back({edge_key(a, b), a < b ? ca : cb, a < b ? cb : ca});
    }
  sorted_runs(sides, [&](size_t i, size_t j) {
    if (j == i + 2 && (sides[i].lo != sides[i + 1].lo || sides[i].hi != sides[i + 1].hi))
      w.seams.insert(w.seams.end(), {uint32_t(sides[i].key >> 32), uint32_t(sides[i].key)});
  });
  return w;
}

std::vector<uint32_t> split_vertex_welded_triangles(const Mesh& mesh) {
  std::vector<uint32_t> tris = mesh.triangles;
  weld_split_vertices(tris, mesh.positions);
  return tris;
}

} // namespace vrs
