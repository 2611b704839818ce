// Per-corner (wedge) and per-face data of a vcglib mesh through a simplification, shared by
// the CLI (tools/) and the MeshLab plugin (plugin/): which edges are seams of that data (the
// core keeps them as constrained edges), and the copy of a corner's data from the input
// corner the core names (vrs::Report::corner_source). Header-only: each side compiles it
// against its own vcglib and mesh type.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <utility>
#include <vector>

namespace vrs_vcg {

// Smooth per-corner normals that turn more than this apart across an edge make it a hard edge
// (a seam); below, the two sides shade one surface. Flat shading (one normal per face) makes
// no seam at all: its hard edges are the geometry's creases, which the feature angle keeps
// when asked. Adapters use the feature angle as the crease angle when it is set.
constexpr double kNormalCreaseDeg = 60.0;

// Which data the mesh really holds (a component may exist in the type but be empty or off).
struct CornerData {
  bool texcoord = false; // wedge texture coordinates, texture index included
  bool normal = false;   // wedge normals
  bool color = false;    // wedge colors
  bool face_color = false;
  // Every face's three corner normals are the same (flat shading): a rebuilt face gets its own
  // normal rather than one of the faces it replaces.
  bool flat_normals = false;
  double normal_crease_deg = kNormalCreaseDeg;
  bool any() const { return texcoord || normal || color || face_color; }
};

namespace detail {

template <class T> bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0; // NaN-safe, and -0 differs from 0 on purpose
}

// Two corner normals of one vertex on either side of an edge shade one surface: equal, or
// both nonzero and within the crease angle.
template <class N> bool smooth_normals(const CornerData& d, const N& a, const N& b) {
  if (same_bits(a, b)) return true;
  const double la = a.Norm(), lb = b.Norm();
  if (!(la > 0) || !(lb > 0)) return false;
  return (a * b) / (la * lb) >= std::cos(d.normal_crease_deg * M_PI / 180.0);
}

template <class Face>
bool same_corner(const CornerData& d, const Face& f, int i, const Face& g, int j) {
  if (d.texcoord && !(same_bits(f.cWT(i).U(), g.cWT(j).U()) &&
                      same_bits(f.cWT(i).V(), g.cWT(j).V()) && f.cWT(i).N() == g.cWT(j).N()))
    return false;
  // Flat normals hold nothing the geometry does not (creases: the feature angle).
  if (d.normal && !d.flat_normals && !smooth_normals(d, f.cWN(i), g.cWN(j))) return false;
  if (d.color && !same_bits(f.cWC(i), g.cWC(j))) return false;
  return true;
}

} // namespace detail

// True when each live face's three corner normals are the same (one normal per face).
template <class Mesh> bool flat_normals(const Mesh& m) {
  for (const auto& f : m.face)
    if (!f.IsD() &&
        !(detail::same_bits(f.cWN(0), f.cWN(1)) && detail::same_bits(f.cWN(0), f.cWN(2))))
      return false;
  return true;
}

// Seams as vertex pairs in the core's numbering: edges across which any of the data differs
// at either end (normals: by more than the crease angle), or whose faces differ in face data
// (a material border is a seam too).
// `vertex_of(face, corner)` gives the core index of a face's corner; `faces` lists the mesh's
// live faces in core order.
template <class Mesh, class VertexOf>
std::vector<uint32_t> seam_edges(const Mesh& m, const CornerData& d,
                                 const std::vector<size_t>& faces, VertexOf vertex_of) {
  using Face = typename Mesh::FaceType;
  struct Seen {
    uint32_t face; // core face index of the first face holding the edge
    uint8_t at_a, at_b;
    bool seam;
  };
  std::vector<uint32_t> out;
  if (!d.any()) return out;
  std::unordered_map<uint64_t, Seen> seen;
  seen.reserve(faces.size() * 2);
  for (uint32_t f = 0; f < faces.size(); ++f) {
    const Face& face = m.face[faces[f]];
    for (int c = 0; c < 3; ++c) {
      uint32_t a = vertex_of(f, c), b = vertex_of(f, (c + 1) % 3);
      uint64_t key = a < b ? uint64_t(a) << 32 | b : uint64_t(b) << 32 | a;
      auto [it, first] = seen.emplace(key, Seen{f, uint8_t(c), uint8_t((c + 1) % 3), false});
      if (first || it->second.seam) continue;
      const Face& other = m.face[faces[it->second.face]];
      // The other face's corners of the same two vertices (its edge may run either way).
      int oa = it->second.at_a, ob = it->second.at_b;
      if (vertex_of(it->second.face, oa) != a) std::swap(oa, ob);
      bool same = detail::same_corner(d, face, c, other, oa) &&
                  detail::same_corner(d, face, (c + 1) % 3, other, ob) &&
                  (!d.face_color || detail::same_bits(face.cC(), other.cC()));
      if (!same) {
        it->second.seam = true;
        out.insert(out.end(), {a, b});
      }
    }
  }
  return out;
}

// Copies corner `i` of `from` to corner `j` of `to`, and the face data when `whole_face`.
// Flat normals are not copied: finish_face gives the face its own.
template <class Face>
void copy_corner(const CornerData& d, const Face& from, int i, Face& to, int j, bool whole_face) {
  if (d.texcoord) to.WT(j) = from.cWT(i);
  if (d.normal && !d.flat_normals) to.WN(j) = from.cWN(i);
  if (d.color) to.WC(j) = from.cWC(i);
  if (whole_face && d.face_color) to.C() = from.cC();
}

// After a rebuilt face's corners are set: with flat normals, the face's own unit normal at
// its three corners (the input's faces are shaded by theirs).
template <class Face> void finish_face(const CornerData& d, Face& f) {
  if (!d.normal || !d.flat_normals) return;
  auto n = (f.cP(1) - f.cP(0)) ^ (f.cP(2) - f.cP(0));
  const auto length = n.Norm();
  if (length > 0) n /= length;
  for (int c = 0; c < 3; ++c)
    f.WN(c).Import(n);
}

// Reverses a face as the core reverses one it reorients (vrs::Report::reoriented_faces):
// corners 1 and 2 swapped with their per-corner data; the faux-edge flags (quads' diagonals)
// follow their edges (edge 0 becomes edge 2 and the other way round).
template <class Face> void reverse_face(const CornerData& d, Face& f) {
  std::swap(f.V(1), f.V(2));
  if (d.texcoord) std::swap(f.WT(1), f.WT(2));
  if (d.normal) std::swap(f.WN(1), f.WN(2));
  if (d.color) std::swap(f.WC(1), f.WC(2));
  const bool faux0 = f.IsF(0), faux2 = f.IsF(2);
  if (faux0)
    f.SetF(2);
  else
    f.ClearF(2);
  if (faux2)
    f.SetF(0);
  else
    f.ClearF(0);
}

} // namespace vrs_vcg
