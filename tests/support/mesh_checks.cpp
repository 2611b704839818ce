#include "mesh_checks.h"

#include "fold_over.h"
#include "mesh/split_vertices.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace vrs_test {

namespace {

uint64_t key(uint32_t a, uint32_t b) {
  if (a > b) std::swap(a, b);
  return (uint64_t(a) << 32) | b;
}

using EdgeCounts = std::unordered_map<uint64_t, int>;

EdgeCounts edge_counts(const vrs::Mesh& m) {
  std::unordered_map<uint64_t, int> c;
  for (size_t i = 0; i < m.triangles.size(); i += 3)
    for (int e = 0; e < 3; ++e)
      ++c[key(m.triangles[i + e], m.triangles[i + (e + 1) % 3])];
  return c;
}

// The faces around v grouped into fans (joined across edges of exactly two faces): group[i]
// is the root of v's i-th face in `faces_at[v]`. False where no split is asked: an edge at v of
// more than two faces, or v's faces disagreeing on their orientation (walking an edge alike).
bool fans_at(const vrs::Mesh& m, const EdgeCounts& edges,
             const std::vector<std::vector<uint32_t>>& faces_at, uint32_t v,
             std::vector<size_t>& group) {
  const auto& fs = faces_at[v];
  group.resize(fs.size());
  for (size_t i = 0; i < fs.size(); ++i)
    group[i] = i;
  auto root = [&](size_t i) {
    while (group[i] != i)
      i = group[i];
    return i;
  };
  std::set<uint32_t> after, before;
  for (uint32_t f : fs) {
    const uint32_t* t = &m.triangles[3 * size_t(f)];
    const int c = t[0] == v ? 0 : t[1] == v ? 1 : 2;
    if (!after.insert(t[(c + 1) % 3]).second || !before.insert(t[(c + 2) % 3]).second) return false;
  }
  for (size_t i = 0; i < fs.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = m.triangles[3 * fs[i] + c];
      if (a == v) continue;
      const int holders = edges.at(key(v, a));
      if (holders > 2) return false;
      if (holders != 2) continue;
      for (size_t j = i + 1; j < fs.size(); ++j)
        for (int d = 0; d < 3; ++d)
          if (m.triangles[3 * fs[j] + d] == a) group[root(j)] = root(i);
    }
  for (size_t i = 0; i < fs.size(); ++i)
    group[i] = root(i);
  return true;
}

std::vector<std::vector<uint32_t>> faces_at(const vrs::Mesh& m) {
  std::vector<std::vector<uint32_t>> at(m.vertex_count());
  for (size_t f = 0; f < m.face_count(); ++f)
    for (int c = 0; c < 3; ++c)
      at[m.triangles[3 * f + c]].push_back(uint32_t(f));
  return at;
}

// Per vertex: 1 where several fans only touch (fans_at agrees to split it).
std::vector<uint8_t> pinches(const vrs::Mesh& m) {
  const EdgeCounts edges = edge_counts(m);
  const auto at = faces_at(m);
  std::vector<uint8_t> pinched(m.vertex_count(), 0);
  std::vector<size_t> group;
  for (uint32_t v = 0; v < m.vertex_count(); ++v)
    if (fans_at(m, edges, at, v, group))
      pinched[v] = std::set<size_t>(group.begin(), group.end()).size() > 1;
  return pinched;
}

// Fans that touch only at a vertex counted apart, at the vertices flagged in `at_pinch`: each
// fan past the first given its own copy of the vertex. The core simplifies such fans apart
// (fan_split.h), so the topology it keeps is this one's.
vrs::Mesh unpinched(const vrs::Mesh& m, const std::vector<uint8_t>& at_pinch) {
  const EdgeCounts edges = edge_counts(m);
  const auto at = faces_at(m);
  vrs::Mesh out = m;
  std::vector<size_t> group;
  for (uint32_t v = 0; v < m.vertex_count(); ++v) {
    if (!at_pinch[v] || !fans_at(m, edges, at, v, group)) continue;
    std::map<size_t, uint32_t> copy_of; // group root -> the vertex its faces name
    for (size_t i = 0; i < group.size(); ++i) {
      if (copy_of.empty()) copy_of[group[i]] = v;
      if (!copy_of.count(group[i])) {
        copy_of[group[i]] = uint32_t(out.vertex_count());
        for (int c = 0; c < 3; ++c)
          out.positions.push_back(m.positions[3 * v + c]);
      }
      uint32_t* t = &out.triangles[3 * size_t(at[v][i])];
      for (int c = 0; c < 3; ++c)
        if (t[c] == v) t[c] = copy_of[group[i]];
    }
  }
  return out;
}

struct V3 {
  double x, y, z;
};
V3 pos(const vrs::Mesh& m, uint32_t v) {
  return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
}
V3 sub(V3 a, V3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
V3 cross(V3 a, V3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot(V3 a, V3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// Per vertex of `in`: its faces' unit normals summed, as the core's vertex normals; none where
// fans only touch (each is a surface of its own, judged by its own normal: fan_split.h), as
// where faces cancel.
std::vector<V3> vertex_normals(const vrs::Mesh& in) {
  std::vector<V3> normal(in.vertex_count(), V3{0, 0, 0});
  for (size_t i = 0; i < in.triangles.size(); i += 3) {
    V3 x = cross(sub(pos(in, in.triangles[i + 1]), pos(in, in.triangles[i])),
                 sub(pos(in, in.triangles[i + 2]), pos(in, in.triangles[i])));
    double l = std::sqrt(dot(x, x));
    if (!(l > 0) || !std::isfinite(l)) continue;
    for (int c = 0; c < 3; ++c) {
      V3& n = normal[in.triangles[i + c]];
      n = {n.x + x.x / l, n.y + x.y / l, n.z + x.z / l};
    }
  }
  const std::vector<uint8_t> pinched = pinches(in);
  for (size_t v = 0; v < pinched.size(); ++v)
    if (pinched[v]) normal[v] = V3{0, 0, 0};
  return normal;
}

// Pieces of other orientations welded (`apart`: the input unwelded, each piece turned to agree
// within itself, as the output holds it; `welded`: the same faces welded): the core judges a
// corner on the welded surface, turned to agree, by every face the weld joins at it (a face of
// the piece across a seam included), and gives the orientation back on output. So: the welded
// surface's normal, in the orientation of the copy's own faces; none where those disagree (a
// copy on the kept line between a turned piece and another).
std::vector<V3> welded_vertex_normals(const vrs::Mesh& apart, const vrs::Mesh& welded) {
  vrs::Mesh run = welded;
  orient_coherently(run);
  const std::vector<V3> at_rep = vertex_normals(run);
  std::vector<V3> normal(apart.vertex_count(), V3{0, 0, 0});
  std::vector<int> turned(apart.vertex_count(), 0);   // 1 kept, -1 turned, 2 both
  std::vector<uint32_t> rep(apart.vertex_count(), 0); // the welded vertex standing for each
  for (size_t f = 0; f < apart.face_count(); ++f) {
    const int t =
        std::equal(&run.triangles[3 * f], &run.triangles[3 * f + 3], &welded.triangles[3 * f]) ? 1
                                                                                               : -1;
    for (int c = 0; c < 3; ++c) {
      const uint32_t v = apart.triangles[3 * f + c];
      int& s = turned[v];
      s = s == 0 || s == t ? t : 2;
      rep[v] = welded.triangles[3 * f + c];
    }
  }
  for (size_t v = 0; v < apart.vertex_count(); ++v) {
    if (turned[v] == 0 || turned[v] == 2) continue;
    const V3 n = at_rep[rep[v]];
    normal[v] = {turned[v] * n.x, turned[v] * n.y, turned[v] * n.z};
  }
  return normal;
}

// Output faces (all, or only those the re-triangulation made) whose normal opposes the input's
// vertex normals (`normal`, per input vertex) at their corners: dot < -tolerance * |face
// normal| * |normal sum|.
size_t flipped_faces(const std::vector<V3>& normal, const vrs::Mesh& out, const vrs::Report& r,
                     bool new_only, double tolerance) {
  std::vector<uint32_t> old_of(out.vertex_count());
  for (size_t v = 0; v < r.remap.size(); ++v)
    if (r.remap[v] != vrs::kRemoved) old_of[r.remap[v]] = uint32_t(v);
  size_t flipped = 0;
  for (size_t f = 0; f < out.face_count(); ++f) {
    if (new_only && r.face_source[f] != vrs::kRemoved) continue;
    const uint32_t* t = &out.triangles[3 * f];
    V3 x = cross(sub(pos(out, t[1]), pos(out, t[0])), sub(pos(out, t[2]), pos(out, t[0])));
    V3 s{0, 0, 0};
    for (int c = 0; c < 3; ++c) {
      V3 n = normal[old_of[t[c]]];
      double l = std::sqrt(dot(n, n));
      // As the core: a sum this short is faces cancelling, no normal.
      if (l > 1e-3) s = {s.x + n.x / l, s.y + n.y / l, s.z + n.z / l};
    }
    flipped += dot(x, s) < -tolerance * std::sqrt(dot(x, x)) * std::sqrt(dot(s, s));
  }
  return flipped;
}

// count_flipped_new given the input's normals: clearly opposed only, beyond rounding (the
// core decides in its own precision).
size_t flipped_new(const std::vector<V3>& normal, const vrs::Mesh& out, const vrs::Report& r) {
  return flipped_faces(normal, out, r, /*new_only=*/true, /*tolerance=*/1e-6);
}

} // namespace

long EdgeStats::euler() const {
  return long(referenced_vertices) - long(edges) + long(faces);
}

namespace {

// The checks below from edge maps built once: check_run reads each mesh's map several times
// (a 19 M-face mesh's map takes seconds to build and gigabytes to hold).
EdgeStats stats_of(const vrs::Mesh& m, const EdgeCounts& edges) {
  EdgeStats s;
  for (auto& [k, n] : edges) {
    ++s.edges;
    s.boundary += n == 1;
    s.nonmanifold += n > 2;
  }
  std::vector<char> used(m.vertex_count(), 0);
  for (uint32_t v : m.triangles)
    used[v] = 1;
  s.referenced_vertices = size_t(std::count(used.begin(), used.end(), 1));
  s.faces = m.face_count();
  return s;
}

std::string boundary_kept(const EdgeCounts& before, const EdgeCounts& after, const vrs::Report& r) {
  for (auto& [k, n] : before) {
    if (n != 1) continue;
    uint32_t a = r.remap[k >> 32], b = r.remap[k & 0xffffffffu];
    if (a == vrs::kRemoved || b == vrs::kRemoved) return "a boundary vertex was removed";
    auto it = after.find(key(a, b));
    if (it == after.end() || it->second != 1) return "a boundary edge was lost";
  }
  return {};
}

std::vector<long> euler_of(const vrs::Mesh& m, const EdgeCounts& edges) {
  const size_t n = m.vertex_count();
  std::vector<uint32_t> parent(n);
  for (size_t v = 0; v < n; ++v)
    parent[v] = uint32_t(v);
  auto find = [&](uint32_t v) {
    while (parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for (size_t i = 0; i < m.triangles.size(); i += 3)
    for (int c = 1; c < 3; ++c)
      parent[find(m.triangles[i + c])] = find(m.triangles[i]);
  std::unordered_map<uint32_t, long> chi;
  std::vector<char> used(n, 0);
  for (uint32_t v : m.triangles)
    if (!used[v]) used[v] = 1, ++chi[find(v)];
  for (auto& [k, c] : edges)
    --chi[find(uint32_t(k >> 32))];
  for (size_t i = 0; i < m.triangles.size(); i += 3)
    ++chi[find(m.triangles[i])];
  std::vector<long> out;
  for (auto& [root, c] : chi)
    out.push_back(c);
  std::sort(out.begin(), out.end());
  return out;
}

// check_valid past the index check, with the non-manifold counts already known.
std::string valid_given(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r,
                        size_t in_nonmanifold, size_t out_nonmanifold) {
  std::string e = check_subset(in, out, r);
  if (e.empty() && out_nonmanifold > in_nonmanifold) e = "new non-manifold edges";
  if (e.empty() && count_duplicate_directed_edges(out) > count_duplicate_directed_edges(in))
    e = "new repeated directed edges (orientation broken)";
  return e;
}

} // namespace

EdgeStats edge_stats(const vrs::Mesh& m) {
  return stats_of(m, edge_counts(m));
}

std::string check_valid(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r) {
  if (!r.ok) return "refused: " + r.message;
  std::string e = check_indices(out);
  if (!e.empty()) return e;
  return valid_given(in, out, r, edge_stats(in).nonmanifold, edge_stats(out).nonmanifold);
}

std::string check_subset(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r) {
  if (r.remap.size() != in.vertex_count()) return "remap has the wrong size";
  uint32_t expect = 0;
  for (size_t v = 0; v < r.remap.size(); ++v) {
    if (r.remap[v] == vrs::kRemoved) continue;
    if (r.remap[v] != expect++) return "remap is not order-preserving at " + std::to_string(v);
    if (std::memcmp(&in.positions[3 * v], &out.positions[3 * r.remap[v]], 3 * sizeof(float)))
      return "vertex " + std::to_string(v) + " moved";
  }
  if (expect != out.vertex_count()) return "output has vertices the remap does not name";
  if (r.face_source.size() != out.face_count()) return "face_source has the wrong size";
  for (size_t f = 0; f < r.face_source.size(); ++f) {
    uint32_t s = r.face_source[f];
    if (s == vrs::kRemoved) continue;
    if (s >= in.face_count()) return "face_source out of range";
    // Reversed (corners 1 and 2 swapped) only where the core reoriented the input.
    bool same = true, reversed = r.reoriented_faces > 0;
    for (int c = 0; c < 3; ++c) {
      same = same && r.remap[in.triangles[3 * s + c]] == out.triangles[3 * f + c];
      reversed = reversed && r.remap[in.triangles[3 * s + (3 - c) % 3]] == out.triangles[3 * f + c];
    }
    if (!same && !reversed)
      return "face " + std::to_string(f) + " is not the input face its source names";
  }
  return {};
}

std::string check_indices(const vrs::Mesh& m) {
  for (size_t i = 0; i < m.triangles.size(); i += 3) {
    uint32_t a = m.triangles[i], b = m.triangles[i + 1], c = m.triangles[i + 2];
    if (a >= m.vertex_count() || b >= m.vertex_count() || c >= m.vertex_count())
      return "index out of range in face " + std::to_string(i / 3);
    if (a == b || b == c || a == c) return "repeated corner in face " + std::to_string(i / 3);
  }
  return {};
}

std::string check_boundary_kept(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r) {
  return boundary_kept(edge_counts(in), edge_counts(out), r);
}

size_t count_degenerate(const vrs::Mesh& m, double q) {
  size_t n = 0;
  for (size_t i = 0; i < m.triangles.size(); i += 3) {
    V3 a = pos(m, m.triangles[i]), b = pos(m, m.triangles[i + 1]), c = pos(m, m.triangles[i + 2]);
    V3 x = cross(sub(b, a), sub(c, a));
    double sum = dot(sub(b, a), sub(b, a)) + dot(sub(c, b), sub(c, b)) + dot(sub(a, c), sub(a, c));
    double quality = sum > 0 ? 2 * std::sqrt(3.0) * std::sqrt(dot(x, x)) / sum : 0;
    n += quality < q;
  }
  return n;
}

size_t count_flipped(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r) {
  return flipped_faces(vertex_normals(in), out, r, /*new_only=*/false, /*tolerance=*/0);
}

size_t count_duplicate_directed_edges(const vrs::Mesh& m) {
  std::unordered_map<uint64_t, int> c;
  size_t dup = 0;
  for (size_t i = 0; i < m.triangles.size(); i += 3)
    for (int e = 0; e < 3; ++e) {
      uint64_t k = (uint64_t(m.triangles[i + e]) << 32) | m.triangles[i + (e + 1) % 3];
      dup += ++c[k] > 1;
    }
  return dup;
}

bool same_bits(const vrs::Mesh& a, const vrs::Mesh& b) {
  if (a.triangles != b.triangles || a.positions.size() != b.positions.size()) return false;
  return a.positions.empty() || std::memcmp(a.positions.data(), b.positions.data(),
                                            a.positions.size() * sizeof(float)) == 0;
}

size_t count_flipped_new(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Report& r) {
  return flipped_new(vertex_normals(in), out, r);
}

std::vector<long> component_euler(const vrs::Mesh& m) {
  const vrs::Mesh apart = unpinched(m, pinches(m));
  return euler_of(apart, edge_counts(apart));
}

bool same_component_euler(const vrs::Mesh& in, const vrs::Mesh& out,
                          const std::vector<uint32_t>& remap) {
  const std::vector<uint8_t> at_in = pinches(in);
  std::vector<uint8_t> at_out(out.vertex_count(), 0);
  for (size_t v = 0; v < at_in.size() && v < remap.size(); ++v)
    if (at_in[v] && remap[v] != vrs::kRemoved && remap[v] < at_out.size()) at_out[remap[v]] = 1;
  const vrs::Mesh a = unpinched(in, at_in), b = unpinched(out, at_out);
  return euler_of(a, edge_counts(a)) == euler_of(b, edge_counts(b));
}

size_t orient_coherently(vrs::Mesh& m) {
  // Written apart from the core's (orientation.cpp), over an edge map: each piece found
  // breadth first from its lowest face; then, piece by piece from the lowest, one that was
  // incoherent and is orientable takes whichever of its two orientations repeats fewer directed
  // edges (counted on all its edges, the faces of pieces before it as they were left), a tie
  // going to the orientation most of its faces had, then its lowest face's; unless both
  // repeat more than it did as given.
  const size_t faces = m.face_count();
  std::unordered_map<uint64_t, std::vector<uint32_t>> by_edge; // undirected edge -> faces
  auto key = [](uint32_t a, uint32_t b) {
    return a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a);
  };
  const auto& t = m.triangles;
  for (size_t f = 0; f < faces; ++f)
    for (int e = 0; e < 3; ++e)
      by_edge[key(t[3 * f + e], t[3 * f + (e + 1) % 3])].push_back(uint32_t(f));
  auto walks = [&](uint32_t f, uint32_t a, uint32_t b) { // does f walk a -> b?
    for (int e = 0; e < 3; ++e)
      if (t[3 * f + e] == a && t[3 * f + (e + 1) % 3] == b) return true;
    return false;
  };
  std::vector<int> flip(faces, -1);    // relative to the piece's lowest face, then final
  std::vector<int> reversal(faces, 0); // as the faces stand now
  std::vector<std::vector<uint32_t>> pieces;
  std::vector<bool> orientable;
  for (size_t seed = 0; seed < faces; ++seed) {
    if (flip[seed] >= 0) continue;
    std::vector<uint32_t> piece{uint32_t(seed)};
    flip[seed] = 0;
    bool ok = true;
    for (size_t i = 0; i < piece.size(); ++i) {
      const uint32_t f = piece[i];
      for (int e = 0; e < 3; ++e) {
        const uint32_t a = t[3 * f + e], b = t[3 * f + (e + 1) % 3];
        const auto& holders = by_edge[key(a, b)];
        if (holders.size() != 2) continue;
        const uint32_t g = holders[0] == f ? holders[1] : holders[0];
        const int want = flip[f] ^ int(walks(g, a, b));
        if (flip[g] >= 0) {
          ok = ok && flip[g] == want;
          continue;
        }
        flip[g] = want;
        piece.push_back(g);
      }
    }
    pieces.push_back(piece);
    orientable.push_back(ok);
  }
  auto repeats = [&](const std::vector<uint32_t>& piece) { // on the piece's edges, as they stand
    std::set<uint64_t> edges;
    for (uint32_t f : piece)
      for (int e = 0; e < 3; ++e)
        edges.insert(key(t[3 * f + e], t[3 * f + (e + 1) % 3]));
    size_t n = 0;
    for (uint64_t k : edges) {
      const uint32_t a = uint32_t(k >> 32), b = uint32_t(k);
      size_t ab = 0, ba = 0;
      for (uint32_t g : by_edge[k]) {
        const bool forward = walks(g, a, b) != bool(reversal[g]);
        ab += forward;
        ba += !forward;
      }
      n += (ab > 1 ? ab - 1 : 0) + (ba > 1 ? ba - 1 : 0);
    }
    return n;
  };
  size_t total = 0;
  for (size_t p = 0; p < pieces.size(); ++p) { // found from the lowest face: already in order
    const auto& piece = pieces[p];
    size_t reversed = 0;
    for (uint32_t f : piece)
      reversed += flip[f];
    if (!orientable[p] || reversed == 0) continue;
    const size_t given = repeats(piece);
    for (uint32_t f : piece)
      reversal[f] = flip[f];
    const size_t found = repeats(piece);
    for (uint32_t f : piece)
      reversal[f] = !flip[f];
    const size_t opposite = repeats(piece);
    if (std::min(found, opposite) > given) {
      for (uint32_t f : piece)
        reversal[f] = 0;
      continue;
    }
    const bool invert = found != opposite ? opposite < found : 2 * reversed > piece.size();
    for (uint32_t f : piece)
      reversal[f] = flip[f] ^ int(invert);
    total += invert ? piece.size() - reversed : reversed;
  }
  for (size_t f = 0; f < faces; ++f)
    if (reversal[f]) std::swap(m.triangles[3 * f + 1], m.triangles[3 * f + 2]);
  return total;
}

vrs::Mesh without_repeated_corner_faces(const vrs::Mesh& m) {
  vrs::Mesh c;
  c.positions = m.positions;
  for (size_t i = 0; i < m.triangles.size(); i += 3) {
    uint32_t a = m.triangles[i], b = m.triangles[i + 1], d = m.triangles[i + 2];
    if (a != b && b != d && a != d) c.triangles.insert(c.triangles.end(), {a, b, d});
  }
  return c;
}

std::string check_corner_sources(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Options& o,
                                 const vrs::Report& r) {
  if (!o.corner_sources) return r.corner_source.empty() ? "" : "corner sources not asked for";
  if (r.corner_source.size() != out.triangles.size()) return "corner_source size differs";
  std::vector<uint32_t> original(out.vertex_count(), vrs::kRemoved);
  for (size_t v = 0; v < r.remap.size(); ++v)
    if (r.remap[v] != vrs::kRemoved) original[r.remap[v]] = uint32_t(v);
  for (size_t c = 0; c < out.triangles.size(); ++c) {
    uint32_t s = r.corner_source[c];
    if (s >= in.triangles.size()) return "corner source out of range";
    if (in.triangles[s] != original[out.triangles[c]])
      return "corner " + std::to_string(c) + " takes the data of another vertex";
  }
  if (!o.constrained_edges || o.constrained_edges->empty()) return {};
  // Charts: input faces joined across every edge that is not constrained.
  const size_t nf = in.face_count();
  std::vector<uint32_t> parent(nf);
  for (size_t f = 0; f < nf; ++f)
    parent[f] = uint32_t(f);
  auto find = [&](uint32_t f) {
    while (parent[f] != f)
      f = parent[f] = parent[parent[f]];
    return f;
  };
  auto key = [](uint32_t a, uint32_t b) {
    return a < b ? uint64_t(a) << 32 | b : uint64_t(b) << 32 | a;
  };
  std::unordered_set<uint64_t> constrained;
  const auto& ce = *o.constrained_edges;
  for (size_t i = 0; i + 1 < ce.size(); i += 2)
    constrained.insert(key(ce[i], ce[i + 1]));
  std::unordered_map<uint64_t, uint32_t> first_face;
  for (size_t f = 0; f < nf; ++f)
    for (int c = 0; c < 3; ++c) {
      uint32_t a = in.triangles[3 * f + c], b = in.triangles[3 * f + (c + 1) % 3];
      if (a == b || constrained.count(key(a, b))) continue;
      auto it = first_face.emplace(key(a, b), uint32_t(f)).first;
      parent[find(uint32_t(f))] = find(it->second);
    }
  for (size_t f = 0; f < out.face_count(); ++f) {
    uint32_t chart = find(r.corner_source[3 * f] / 3);
    for (int c = 1; c < 3; ++c)
      if (find(r.corner_source[3 * f + c] / 3) != chart)
        return "output face " + std::to_string(f) + " spans two charts";
  }
  return {};
}

std::string check_run(const vrs::Mesh& in, const vrs::Mesh& out, const vrs::Options& o,
                      const vrs::Report& r) {
  if (!r.ok) {
    if (r.message.empty()) return "refused without a message";
    if (!same_bits(out, in)) return "refused but the mesh changed";
    return {};
  }
  std::string e = check_indices(out); // before anything indexes with them
  if (!e.empty()) return e;
  // Split vertices the core welded (Report::welded_vertices): the surface is judged as the
  // core read it, the input welded and the output's copies put back onto the copies standing
  // for them, both in the input's numbering; the raw output answers for its vertices and
  // corners (subset, counts, corner sources).
  vrs::Mesh in_w, out_w;
  vrs::Report r_w;
  const vrs::Mesh *src = &in, *dst = &out;
  const vrs::Report* rr = &r;
  // Pieces written in different orientations and welded (split_vertices.h) are given back
  // their own: the output holds the orientation of the pieces apart, each turned to agree
  // within itself (a shuffled piece), and is judged against the input so oriented.
  bool pieces_apart = false;
  size_t apart_reoriented = 0;
  vrs::Mesh apart;
  if (r.welded_vertices) {
    in_w = in;
    const vrs::Welding w = vrs::weld_split_vertices(in_w.triangles, in_w.positions);
    apart = without_repeated_corner_faces(in);
    if (count_duplicate_directed_edges(without_repeated_corner_faces(in_w)) >
        count_duplicate_directed_edges(apart)) { // welded edges walked the same way
      pieces_apart = true;
      apart_reoriented = orient_coherently(apart);
      in_w.triangles = apart.triangles;
      for (uint32_t& v : in_w.triangles)
        v = w.rep.empty() ? v : w.rep[v];
    }
    if (w.welded != r.welded_vertices) return "welded_vertices differs from the welding's count";
    std::vector<uint32_t> input_of(out.vertex_count(), 0);
    r_w = r;
    for (size_t i = 0; i < r.remap.size(); ++i)
      if (r.remap[i] != vrs::kRemoved)
        input_of[r.remap[i]] = uint32_t(i), r_w.remap[i] = uint32_t(i);
    out_w.positions = in.positions;
    for (uint32_t v : out.triangles)
      out_w.triangles.push_back(w.rep[input_of[v]]);
    src = &in_w, dst = &out_w, rr = &r_w;
  }
  // Each edge map once; the input's own only when it differs from the cleaned one.
  // The surface as the core reads it: reoriented where the core says it did.
  vrs::Mesh clean = without_repeated_corner_faces(*src);
  if (pieces_apart ? apart_reoriented != r.reoriented_faces
                   : r.reoriented_faces && orient_coherently(clean) != r.reoriented_faces)
    return "reoriented_faces differs from the faces a coherent orientation reverses";
  const EdgeCounts clean_edges = edge_counts(clean), out_edges = edge_counts(*dst);
  const EdgeStats before = stats_of(clean, clean_edges), after = stats_of(*dst, out_edges);
  const size_t in_nonmanifold = clean.face_count() == src->face_count()
                                    ? before.nonmanifold
                                    : stats_of(*src, edge_counts(*src)).nonmanifold;
  e = valid_given(in, out, r, in_nonmanifold, after.nonmanifold);
  if (!e.empty()) return e;
  if (r.faces != out.face_count() || r.vertices != out.vertex_count())
    return "report counts differ from the mesh";
  if (after.boundary > before.boundary) return "new boundary edges";
  if (!o.simplify_boundary && !r.boundary_simplified) {
    e = boundary_kept(clean_edges, out_edges, *rr);
    if (!e.empty()) return e;
  }
  if (count_degenerate(*dst) > count_degenerate(clean)) return "new degenerate faces";
  // The corners' normals are the promise while the input-normal veto holds; it is eased, then
  // lifted (Report::relaxed_removals) to reach a target, the fold-over check below holds always.
  // Pieces of other orientations welded: their faces' normals cancel at the welded vertices,
  // where the core judged them turned to agree; the output's corners name the copies, each
  // in its own piece's orientation (welded_vertex_normals).
  if (size_t f = r.relaxed_removals ? 0
                 : pieces_apart     ? flipped_new(welded_vertex_normals(apart, in_w), out, r)
                                    : count_flipped_new(clean, *dst, *rr))
    return std::to_string(f) + " new faces flipped against the input surface";
  if (size_t f = count_fold_overs(clean, *dst, *rr))
    return std::to_string(f) + " new faces fold over (against every input face near them)";
  // As given, or with the fans that only touch at a vertex apart where the core split them
  // (fan_split.h): where it did not (faces whose orientations disagree there, constraints),
  // the topology as given is what it keeps.
  if (euler_of(*dst, out_edges) != euler_of(clean, clean_edges) &&
      !same_component_euler(clean, *dst, rr->remap))
    return "a component's Euler characteristic changed";
  e = check_corner_sources(in, out, o, r);
  if (!e.empty()) return e;

  const vrs::TargetKind k = o.target.kind;
  const size_t target_faces =
      k == vrs::TargetKind::Faces ? o.target.faces
      : k == vrs::TargetKind::Ratio
          ? size_t(std::llround(o.target.ratio * double(clean.face_count())))
          : 0;
  switch (r.stop) {
  case vrs::StopReason::TargetReached:
    if ((k == vrs::TargetKind::Faces || k == vrs::TargetKind::Ratio) &&
        out.face_count() > target_faces)
      return "target_reached with " + std::to_string(out.face_count()) + " faces for " +
             std::to_string(target_faces);
    if (k == vrs::TargetKind::Vertices && after.referenced_vertices > o.target.vertices)
      return "target_reached above the vertex target";
    if (k == vrs::TargetKind::MaxFactor || k == vrs::TargetKind::Auto)
      return "target_reached for a target kind that has no count";
    break;
  case vrs::StopReason::MaxFactor:
    if (k != vrs::TargetKind::MaxFactor) return "max_factor stop without that target";
    // The report keeps priorities in float: allow its rounding.
    if (r.max_removed_factor > o.target.max_factor * (1 + 1e-6) + 1e-30)
      return "removed a vertex above max_factor";
    break;
  case vrs::StopReason::LastInterval:
    if (k != vrs::TargetKind::Auto) return "last_interval stop without the auto target";
    break;
  case vrs::StopReason::NoCandidates:
    if (k == vrs::TargetKind::Faces || k == vrs::TargetKind::Ratio) {
      if (out.face_count() <= target_faces) return "no_candidates but the target was met";
    } else if (k == vrs::TargetKind::Vertices) {
      if (after.referenced_vertices <= o.target.vertices)
        return "no_candidates but the target was met";
    } else {
      return "no_candidates for a target kind without a count";
    }
    break;
  case vrs::StopReason::Cancelled:
    if (!o.progress) return "cancelled without a progress callback";
    break;
  case vrs::StopReason::InvalidInput: return "ok report with stop invalid_input";
  case vrs::StopReason::ErrorBound:
    if (!(o.max_error > 0 && std::isfinite(o.max_error)))
      return "error_bound stop without a finite max_error";
    break;
  }
  if (o.max_error > 0 && !(r.error_bound <= o.max_error))
    return "certified bound " + std::to_string(r.error_bound) + " above max_error " +
           std::to_string(o.max_error);
  if (!(o.max_error > 0) && r.error_bound != 0) return "an error bound without max_error";
  const bool reached =
      r.stop == vrs::StopReason::TargetReached || r.stop == vrs::StopReason::MaxFactor ||
      r.stop == vrs::StopReason::LastInterval || r.stop == vrs::StopReason::ErrorBound;
  if (r.target_reached != reached) return "target_reached disagrees with the stop reason";
  return {};
}

std::string check_rerun(const vrs::Mesh& in, const vrs::Options& o, const vrs::Mesh& first,
                        const vrs::Report& first_report) {
  // On another thread count: the output must not depend on it either.
  vrs::Options other = o;
  other.threads = o.threads == 1 ? 2 : 1;
  vrs::Mesh again = in;
  const vrs::Report r = vrs::simplify(again, other);
  if (!same_bits(first, again) || r.stop != first_report.stop || r.removed != first_report.removed)
    return "two runs on the same input differ (threads " + std::to_string(o.threads) + " and " +
           std::to_string(other.threads) + ")";
  return {};
}

bool stops_faithfully(const vrs::Report& r) {
  return r.stop_cause == vrs::StopCause::PriceJump ||
         r.stop_detail.find("would fold") != std::string::npos;
}

std::map<std::array<float, 6>, int> edges_by_position(const vrs::Mesh& m) {
  std::map<std::array<float, 6>, int> count;
  for (size_t f = 0; f < m.face_count(); ++f)
    for (int c = 0; c < 3; ++c) {
      const float* a = &m.positions[3 * m.triangles[3 * f + c]];
      const float* b = &m.positions[3 * m.triangles[3 * f + (c + 1) % 3]];
      if (std::lexicographical_compare(b, b + 3, a, a + 3)) std::swap(a, b);
      ++count[{a[0], a[1], a[2], b[0], b[1], b[2]}];
    }
  return count;
}

} // namespace vrs_test
