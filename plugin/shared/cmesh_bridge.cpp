#include "cmesh_bridge.h"

#include <numeric>
#include <unordered_map>

#include <vcg/complex/algorithms/update/topology.h>

namespace vrs_plugin {

namespace {

// A faux edge is flagged on both its faces, and only two faces have it; polygon export walks
// faux edges to rebuild polygons. One flagged on one side only (a face rebuilt, or a file
// that flags it so), or on an edge of more than two faces (a polygon written twice, once
// whole and once as triangles), must go, or the walk runs off into faces that are not its
// polygon (pymeshlab's default OBJ and OFF saves threw std::bad_alloc).
void clear_unpaired_faux_edges(CMeshO& m) {
  struct Count {
    int faces = 0, flagged = 0;
  };
  std::unordered_map<uint64_t, Count> edges;
  auto key = [&](const CFaceO& f, int e) {
    uint64_t a = vcg::tri::Index(m, f.cV(e)), b = vcg::tri::Index(m, f.cV((e + 1) % 3));
    return a < b ? a << 32 | b : b << 32 | a;
  };
  for (const CFaceO& f : m.face)
    for (int e = 0; e < 3; ++e)
      if (!f.IsD() && f.IsF(e)) edges[key(f, e)].flagged++;
  if (edges.empty()) return;
  for (const CFaceO& f : m.face)
    for (int e = 0; e < 3; ++e)
      if (!f.IsD()) {
        const auto it = edges.find(key(f, e));
        if (it != edges.end()) it->second.faces++;
      }
  for (CFaceO& f : m.face)
    for (int e = 0; e < 3; ++e)
      if (!f.IsD() && f.IsF(e)) {
        const Count& c = edges[key(f, e)];
        if (c.flagged != 2 || c.faces != 2) f.ClearF(e);
      }
}

// A polygon loaded from a file (a quad, a pentagon, any size) is a set of triangles joined by
// faux edges. After the filter it survives whole, or what is left of it is plain triangles:
// a pentagon that lost one triangle would otherwise be written as a quad no input had.
void break_lost_polygons(CMeshO& m, const CoreCopy& c, const std::vector<char>& survives) {
  std::vector<uint32_t> parent(c.face.size());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto find = [&](uint32_t f) {
    while (parent[f] != f)
      f = parent[f] = parent[parent[f]];
    return f;
  };
  std::unordered_map<uint64_t, uint32_t> first; // faux edge -> the first face flagging it
  for (uint32_t f = 0; f < c.face.size(); ++f) {
    const CFaceO& face = m.face[c.face[f]];
    for (int e = 0; e < 3; ++e) {
      if (!face.IsF(e)) continue;
      const uint64_t a = vcg::tri::Index(m, face.cV(e)),
                     b = vcg::tri::Index(m, face.cV((e + 1) % 3));
      const auto [it, fresh] = first.emplace(a < b ? a << 32 | b : b << 32 | a, f);
      if (!fresh) parent[find(f)] = find(it->second);
    }
  }
  std::vector<char> lost(c.face.size(), 0);
  for (uint32_t f = 0; f < c.face.size(); ++f)
    if (!survives[f]) lost[find(f)] = 1;
  for (uint32_t f = 0; f < c.face.size(); ++f)
    if (survives[f] && lost[find(f)])
      for (int e = 0; e < 3; ++e)
        m.face[c.face[f]].ClearF(e);
}

} // namespace

CoreCopy to_core(CMeshO& m) {
  CoreCopy c;
  std::vector<uint32_t>& index = c.index;
  index.assign(m.vert.size(), vrs::kRemoved);
  std::vector<double> xyz; // MeshLab's scalars (double in 2022.02 and later)
  xyz.reserve(3 * size_t(m.vn));
  c.vertex.reserve(size_t(m.vn));
  for (size_t i = 0; i < m.vert.size(); ++i) {
    CVertexO& v = m.vert[i];
    if (v.IsD()) continue;
    index[i] = static_cast<uint32_t>(c.vertex.size());
    c.vertex.push_back(&v);
    for (int k = 0; k < 3; ++k)
      xyz.push_back(double(v.P()[k]));
  }
  // As the command line and the numpy API read the same coordinates: the same run.
  c.mesh.positions = vrs::float_positions(xyz.data(), c.vertex.size());
  c.mesh.triangles.reserve(3 * size_t(m.fn));
  c.face.reserve(size_t(m.fn));
  for (size_t i = 0; i < m.face.size(); ++i) {
    CFaceO& f = m.face[i];
    if (f.IsD()) continue;
    c.face.push_back(i);
    for (int k = 0; k < 3; ++k)
      c.mesh.triangles.push_back(index[vcg::tri::Index(m, f.V(k))]);
  }
  return c;
}

std::vector<uint8_t> polygon_faces(const CMeshO& m, const CoreCopy& c) {
  std::vector<uint8_t> polygon(c.face.size(), 0);
  bool any = false;
  for (size_t f = 0; f < c.face.size(); ++f) {
    const CFaceO& face = m.face[c.face[f]];
    polygon[f] = face.IsF(0) || face.IsF(1) || face.IsF(2);
    any = any || polygon[f];
  }
  if (!any) polygon.clear();
  return polygon;
}

vrs_vcg::CornerData corner_data(const MeshModel& m, double feature_angle) {
  vrs_vcg::CornerData d;
  d.texcoord = m.hasDataMask(MeshModel::MM_WEDGTEXCOORD);
  d.normal = m.hasDataMask(MeshModel::MM_WEDGNORMAL);
  d.color = m.hasDataMask(MeshModel::MM_WEDGCOLOR);
  d.face_color = m.hasDataMask(MeshModel::MM_FACECOLOR);
  d.flat_normals = d.normal && vrs_vcg::flat_normals(m.cm);
  if (feature_angle > 0) d.normal_crease_deg = feature_angle;
  return d;
}

std::vector<uint32_t> seams(const CMeshO& m, const CoreCopy& c, const vrs_vcg::CornerData& d) {
  return vrs_vcg::seam_edges(m, d, c.face,
                             [&](uint32_t f, int k) { return c.mesh.triangles[3 * f + k]; });
}

std::vector<uint8_t> vertex_locks(const CMeshO& m, const CoreCopy& c, bool selected_only) {
  bool edges = false;
  for (const auto& e : m.edge)
    edges = edges || !e.IsD();
  if (!edges && !selected_only) return {};
  std::vector<uint8_t> lock(c.vertex.size(), 0);
  for (const auto& e : m.edge)
    if (!e.IsD())
      for (int k = 0; k < 2; ++k) {
        const uint32_t v = c.index[vcg::tri::Index(m, e.cV(k))];
        if (v != vrs::kRemoved) lock[v] = 1;
      }
  if (selected_only)
    for (size_t f = 0; f < c.face.size(); ++f)
      if (!m.face[c.face[f]].IsS())
        for (int k = 0; k < 3; ++k)
          lock[c.mesh.triangles[3 * f + k]] = 1;
  return lock;
}

void apply(CMeshO& m, const CoreCopy& c, const vrs::Mesh& out, const vrs::Report& r,
           bool select_new_faces, const vrs_vcg::CornerData& d) {
  // Every allocation first: if one fails, the mesh has not been touched yet.
  std::vector<CVertexO*> kept(out.vertex_count(), nullptr);
  std::vector<char> survives(c.face.size(), 0);
  size_t fresh = 0;
  for (uint32_t s : r.face_source) {
    if (s == vrs::kRemoved)
      ++fresh;
    else
      survives[s] = 1;
  }
  for (size_t v = 0; v < r.remap.size(); ++v)
    if (r.remap[v] != vrs::kRemoved) kept[r.remap[v]] = c.vertex[v];
  // New faces before any deletion: AddFaces may move the face vector (it mends the adjacency
  // pointers itself) and is the last step that can fail. Vertices do not move.
  auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(m, fresh);
  for (size_t t = 0; t < r.face_source.size(); ++t) {
    if (r.face_source[t] != vrs::kRemoved) continue;
    for (int k = 0; k < 3; ++k) {
      fi->V(k) = kept[out.triangles[3 * t + k]];
      if (d.any()) {
        const uint32_t source = r.corner_source[3 * t + k];
        vrs_vcg::copy_corner(d, m.face[c.face[source / 3]], int(source % 3), *fi, k, k == 0);
      }
    }
    vrs_vcg::finish_face(d, *fi);
    if (select_new_faces) fi->SetS();
    ++fi;
  }
  // Faces the core reoriented keep their place, reversed.
  for (size_t t = 0; t < r.face_source.size(); ++t) {
    const uint32_t s = r.face_source[t];
    if (s == vrs::kRemoved) continue;
    CFaceO& f = m.face[c.face[s]];
    if (f.V(1) != kept[out.triangles[3 * t + 1]]) vrs_vcg::reverse_face(d, f);
  }
  break_lost_polygons(m, c, survives);
  for (size_t f = 0; f < c.face.size(); ++f)
    if (!survives[f]) vcg::tri::Allocator<CMeshO>::DeleteFace(m, m.face[c.face[f]]);
  for (size_t v = 0; v < r.remap.size(); ++v)
    if (r.remap[v] == vrs::kRemoved) vcg::tri::Allocator<CMeshO>::DeleteVertex(m, *c.vertex[v]);
  vcg::tri::Allocator<CMeshO>::CompactEveryVector(m);
  clear_unpaired_faux_edges(m);
  // Adjacency the mesh carries (other filters may have enabled it) must describe the new faces.
  if (vcg::tri::HasFFAdjacency(m)) vcg::tri::UpdateTopology<CMeshO>::FaceFace(m);
  if (vcg::tri::HasVFAdjacency(m)) vcg::tri::UpdateTopology<CMeshO>::VertexFace(m);
}

} // namespace vrs_plugin
