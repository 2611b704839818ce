#include "mesh_io.h"

#include <fstream>
#include <sstream>

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/export.h>
#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/import.h>

namespace vrs_tool {

namespace {

class Vertex;
class Face;
struct Types : public vcg::UsedTypes<vcg::Use<Vertex>::AsVertexType, vcg::Use<Face>::AsFaceType> {};
class Vertex
    : public vcg::Vertex<Types, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::Color4b,
                         vcg::vertex::Qualityf, vcg::vertex::TexCoord2f, vcg::vertex::BitFlags> {};
class Face : public vcg::Face<Types, vcg::face::VertexRef, vcg::face::BitFlags> {};
class VcgMesh : public vcg::tri::TriMesh<std::vector<Vertex>, std::vector<Face>> {};

bool ends_with(std::string s, const std::string &suffix) {
  for (char &c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

} // namespace

class VcgDocument {
 public:
  VcgMesh mesh;
  int mask = 0;
};

namespace {

// OBJ positions and faces (polygons fanned, negative indices relative), with the common
// "v x y z r g b" colour extension. vcglib 2020.09's OBJ importer drops every triangle that
// uses the file's first vertex (it checks the 1-based index after making it 0-based), so OBJ
// is read here; writing still goes through vcglib.
std::string read_obj(const std::string &path, VcgDocument &doc) {
  std::ifstream in(path);
  if (!in) return "cannot open file";
  VcgMesh &m = doc.mesh;
  std::vector<vcg::Point3f> pos;
  std::vector<vcg::Color4b> color;
  std::vector<int> tris;
  std::string line;
  size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      float x, y, z, r, g, b;
      if (!(s >> x >> y >> z)) return "bad vertex on line " + std::to_string(line_no);
      pos.emplace_back(x, y, z);
      if (s >> r >> g >> b) color.emplace_back(vcg::Color4b(r * 255, g * 255, b * 255, 255));
    } else if (tag == "f") {
      std::vector<int> poly;
      std::string corner;
      while (s >> corner) {
        long i = std::strtol(corner.c_str(), nullptr, 10); // "i", "i/t", "i/t/n", "i//n"
        long idx = i > 0 ? i - 1 : long(pos.size()) + i;
        if (i == 0 || idx < 0 || idx >= long(pos.size()))
          return "face on line " + std::to_string(line_no) + " names a missing vertex";
        poly.push_back(int(idx));
      }
      for (size_t j = 1; j + 1 < poly.size(); ++j)
        tris.insert(tris.end(), {poly[0], poly[j], poly[j + 1]});
    }
  }
  auto vi = vcg::tri::Allocator<VcgMesh>::AddVertices(m, pos.size());
  const bool colored = !color.empty() && color.size() == pos.size();
  for (size_t i = 0; i < pos.size(); ++i, ++vi) {
    vi->P() = pos[i];
    if (colored) vi->C() = color[i];
  }
  auto fi = vcg::tri::Allocator<VcgMesh>::AddFaces(m, tris.size() / 3);
  for (size_t t = 0; t < tris.size(); t += 3, ++fi)
    for (int c = 0; c < 3; ++c)
      fi->V(c) = &m.vert[tris[t + c]];
  doc.mask = vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_FACEINDEX |
             (colored ? vcg::tri::io::Mask::IOM_VERTCOLOR : 0);
  return {};
}

} // namespace

LoadResult load(const std::string &path) {
  LoadResult r;
  auto *doc = new VcgDocument;
  if (ends_with(path, ".obj")) {
    std::string err = read_obj(path, *doc);
    if (!err.empty()) {
      r.error = "cannot read " + path + ": " + err;
      delete doc;
    } else {
      r.doc = doc;
    }
    return r;
  }
  int err = vcg::tri::io::Importer<VcgMesh>::Open(doc->mesh, path.c_str(), doc->mask);
  if (err != 0 && vcg::tri::io::Importer<VcgMesh>::ErrorCritical(err)) {
    r.error =
        std::string("cannot read ") + path + ": " + vcg::tri::io::Importer<VcgMesh>::ErrorMsg(err);
    delete doc;
    return r;
  }
  // STL stores a triangle soup: its corners must be merged to have any topology at all.
  if (ends_with(path, ".stl")) {
    vcg::tri::Clean<VcgMesh>::RemoveDuplicateVertex(doc->mesh);
    vcg::tri::Allocator<VcgMesh>::CompactEveryVector(doc->mesh);
  }
  r.doc = doc;
  return r;
}

void close(VcgDocument *doc) {
  delete doc;
}

vrs::Mesh to_core(const VcgDocument &doc) {
  const VcgMesh &m = doc.mesh;
  vrs::Mesh out;
  out.positions.reserve(3 * m.vert.size());
  for (const Vertex &v : m.vert)
    for (int c = 0; c < 3; ++c)
      out.positions.push_back(v.cP()[c]);
  out.triangles.reserve(3 * m.face.size());
  for (const Face &f : m.face) {
    if (f.IsD()) continue;
    for (int c = 0; c < 3; ++c)
      out.triangles.push_back(static_cast<uint32_t>(vcg::tri::Index(m, f.cV(c))));
  }
  return out;
}

void apply(VcgDocument &doc, const vrs::Mesh &simplified, const vrs::Report &report) {
  VcgMesh &m = doc.mesh;
  std::vector<uint32_t> old_of(simplified.vertex_count());
  for (size_t v = 0; v < report.remap.size(); ++v) {
    if (report.remap[v] == vrs::kRemoved)
      vcg::tri::Allocator<VcgMesh>::DeleteVertex(m, m.vert[v]);
    else
      old_of[report.remap[v]] = static_cast<uint32_t>(v);
  }
  for (Face &f : m.face)
    if (!f.IsD()) vcg::tri::Allocator<VcgMesh>::DeleteFace(m, f);
  auto fi = vcg::tri::Allocator<VcgMesh>::AddFaces(m, simplified.face_count());
  for (size_t t = 0; t < simplified.face_count(); ++t, ++fi)
    for (int c = 0; c < 3; ++c)
      fi->V(c) = &m.vert[old_of[simplified.triangles[3 * t + c]]];
  vcg::tri::Allocator<VcgMesh>::CompactEveryVector(m);
  vcg::tri::UpdateBounding<VcgMesh>::Box(m);
}

std::string save(VcgDocument &doc, const std::string &path, bool ascii) {
  // Per-vertex data survives; per-face and per-wedge data do not (the faces are new).
  using vcg::tri::io::Mask;
  int mask = doc.mask & (Mask::IOM_VERTCOORD | Mask::IOM_VERTNORMAL | Mask::IOM_VERTCOLOR |
                         Mask::IOM_VERTQUALITY | Mask::IOM_VERTTEXCOORD | Mask::IOM_VERTFLAGS);
  int err;
  if (ends_with(path, ".ply")) {
    err = vcg::tri::io::ExporterPLY<VcgMesh>::Save(doc.mesh, path.c_str(), mask, !ascii);
    if (err)
      return std::string("cannot write ") + path + ": " +
             vcg::tri::io::ExporterPLY<VcgMesh>::ErrorMsg(err);
    return {};
  }
  err = vcg::tri::io::Exporter<VcgMesh>::Save(doc.mesh, path.c_str(), mask);
  if (err)
    return std::string("cannot write ") + path + ": " +
           vcg::tri::io::Exporter<VcgMesh>::ErrorMsg(err);
  return {};
}

} // namespace vrs_tool
