#include "mesh_io.h"

#include "vcg_mesh.h"
#include "vrs/tiled.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/export.h>
#include <wrap/io_trimesh/export_ply.h>

#include "exact_vertices.h"
#include <wrap/io_trimesh/import.h>

namespace vrs_tool {

namespace {

bool ends_with(std::string s, const std::string& suffix) {
  for (char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// STL's corners merged by position, as vcglib's Clean::RemoveDuplicateVertex merges them (the
// same order: position, then index; the lowest index of equal positions stays; -0 and 0 are
// one position), with an index table where it keeps a std::map of pointers: the command on a
// 1.2 M-face STL took 4.3 s instead of 7.2 s. A NaN coordinate equals nothing and would break the
// sort's ordering (undefined behaviour): such vertices stay apart, unsorted.
void weld_stl_corners(VcgMesh& m) {
  const size_t n = m.vert.size();
  auto position_less = [&](uint32_t a, uint32_t b) {
    const auto &p = m.vert[a].cP(), &q = m.vert[b].cP();
    return p == q ? a < b : p < q;
  };
  std::vector<uint32_t> order;
  order.reserve(n);
  for (uint32_t v = 0; v < n; ++v) {
    const auto& p = m.vert[v].cP();
    if (p[0] == p[0] && p[1] == p[1] && p[2] == p[2]) order.push_back(v);
  }
  std::sort(order.begin(), order.end(), position_less);
  std::vector<uint32_t> to(n);
  for (uint32_t v = 0; v < n; ++v)
    to[v] = v;
  for (size_t i = 1, head = 0; i < order.size(); ++i) {
    if (m.vert[order[i]].cP() == m.vert[order[head]].cP()) {
      to[order[i]] = order[head];
      vcg::tri::Allocator<VcgMesh>::DeleteVertex(m, m.vert[order[i]]);
    } else {
      head = i;
    }
  }
  for (Face& f : m.face)
    if (!f.IsD())
      for (int c = 0; c < 3; ++c)
        f.V(c) = &m.vert[to[vcg::tri::Index(m, f.V(c))]];
}

} // namespace

void VcgDocument::enable(int bits) {
  using vcg::tri::io::Mask;
  if ((bits & Mask::IOM_WEDGTEXCOORD) && !mesh.face.IsWedgeTexCoordEnabled())
    mesh.face.EnableWedgeTexCoord();
  if ((bits & Mask::IOM_WEDGNORMAL) && !mesh.face.IsWedgeNormalEnabled())
    mesh.face.EnableWedgeNormal();
  if ((bits & Mask::IOM_FACECOLOR) && !mesh.face.IsColorEnabled()) mesh.face.EnableColor();
}

vrs_vcg::CornerData VcgDocument::corner_data() const {
  using vcg::tri::io::Mask;
  vrs_vcg::CornerData d;
  d.texcoord = (mask & Mask::IOM_WEDGTEXCOORD) && mesh.face.IsWedgeTexCoordEnabled();
  d.normal = (mask & Mask::IOM_WEDGNORMAL) && mesh.face.IsWedgeNormalEnabled();
  d.face_color = (mask & Mask::IOM_FACECOLOR) && mesh.face.IsColorEnabled();
  d.flat_normals = d.normal && vrs_vcg::flat_normals(mesh);
  if (feature_angle_deg > 0) d.normal_crease_deg = feature_angle_deg;
  return d;
}

LoadResult load(const std::string& path) {
  LoadResult r;
  auto* doc = new VcgDocument;
  std::string error;
  std::error_code size_error;
  try {
    if (std::filesystem::is_regular_file(path, size_error) &&
        std::filesystem::file_size(path, size_error) == 0) {
      error = "the mesh has no faces (the file is empty)"; // in every format alike
    } else if (ends_with(path, ".obj")) {
      error = read_obj(path, *doc);
    } else if (ends_with(path, ".stl")) {
      error = read_stl(path, *doc);
    } else if (ends_with(path, ".off")) {
      error = read_off(path, *doc);
    } else if (!(error = vrs::tiled::check_mesh_file(path)).empty()) {
      // The streaming reader first, in constant memory: vcglib allocates what a header
      // declares (4e9 vertices: an allocator's message) and reads a list of 4e9 indices that
      // holds three as one face with one corner missing.
    } else {
      // vcglib reads into the optional components only when they are on: ask the file first.
      int wanted = 0;
      if (vcg::tri::io::Importer<VcgMesh>::LoadMask(path.c_str(), wanted)) doc->enable(wanted);
      int err = vcg::tri::io::Importer<VcgMesh>::Open(doc->mesh, path.c_str(), doc->mask);
      if (err != 0 && vcg::tri::io::Importer<VcgMesh>::ErrorCritical(err))
        error = vcg::tri::io::Importer<VcgMesh>::ErrorMsg(err);
    }
  } catch (const std::exception&) { // a malformed file asking for absurd allocations
    // Never the library's own words ("vector::_M_default_append"): they say nothing to a user.
    error = "malformed file: it declares more than it holds";
  }
  if (!error.empty()) {
    r.error = "cannot read " + path + ": " + error;
    delete doc;
    return r;
  }
  // STL stores a triangle soup: its corners must be merged to have any topology at all. A face
  // merged into a degenerate one stays: the core drops and counts it, as for every format.
  if (ends_with(path, ".stl")) {
    weld_stl_corners(doc->mesh);
    vcg::tri::Allocator<VcgMesh>::CompactEveryVector(doc->mesh);
  }
  if (doc->mesh.fn == 0) { // as the core, the numpy API and the MeshLab filter refuse it
    r.error = "cannot read " + path + ": the mesh has no faces";
    delete doc;
    return r;
  }
  r.doc = doc;
  return r;
}

void close(VcgDocument* doc) {
  delete doc;
}

vrs::Mesh to_core(const VcgDocument& doc) {
  const VcgMesh& m = doc.mesh;
  vrs::Mesh out;
  out.positions.reserve(3 * m.vert.size());
  for (const Vertex& v : m.vert)
    for (int c = 0; c < 3; ++c)
      out.positions.push_back(v.cP()[c]);
  out.triangles.reserve(3 * m.face.size());
  for (const Face& f : m.face) {
    if (f.IsD()) continue;
    for (int c = 0; c < 3; ++c)
      out.triangles.push_back(static_cast<uint32_t>(vcg::tri::Index(m, f.cV(c))));
  }
  return out;
}

void set_feature_angle(VcgDocument& doc, double degrees) {
  doc.feature_angle_deg = degrees;
}

bool has_corner_data(const VcgDocument& doc) {
  return doc.corner_data().any();
}

bool has_seam_data(const VcgDocument& doc) {
  const vrs_vcg::CornerData d = doc.corner_data();
  return d.texcoord || d.color || d.face_color || (d.normal && !d.flat_normals);
}

bool has_vertex_data(const VcgDocument& doc, const std::string& path) {
  using Mask = vcg::tri::io::Mask;
  if (doc.mask & (Mask::IOM_VERTNORMAL | Mask::IOM_VERTCOLOR | Mask::IOM_VERTQUALITY |
                  Mask::IOM_VERTTEXCOORD | Mask::IOM_VERTRADIUS))
    return true;
  // A PLY's vertex element may hold properties vcglib does not read (kept by ExactVertices).
  std::ifstream f(path, std::ios::binary);
  std::string line;
  if (!std::getline(f, line) || line.rfind("ply", 0) != 0) return false;
  bool in_vertex = false;
  while (std::getline(f, line) && line.rfind("end_header", 0) != 0) {
    std::istringstream words(line);
    std::string kind, a, b, c;
    words >> kind >> a >> b >> c;
    if (kind == "element") in_vertex = a == "vertex";
    if (kind != "property" || !in_vertex) continue;
    const std::string& name = a == "list" ? c : b;
    if (name != "x" && name != "y" && name != "z") return true;
  }
  return false;
}

std::vector<uint32_t> seams(const VcgDocument& doc, const vrs::Mesh& core) {
  const VcgMesh& m = doc.mesh;
  std::vector<size_t> faces;
  for (size_t f = 0; f < m.face.size(); ++f)
    if (!m.face[f].IsD()) faces.push_back(f);
  return vrs_vcg::seam_edges(m, doc.corner_data(), faces,
                             [&](uint32_t f, int c) { return core.triangles[3 * f + c]; });
}

std::vector<uint8_t> polygon_faces(const VcgDocument& doc, size_t face_count) {
  return doc.polygons.face_flags(face_count);
}

void apply(VcgDocument& doc, const vrs::Mesh& simplified, const vrs::Report& report) {
  VcgMesh& m = doc.mesh;
  if (!doc.polygons.empty()) { // the input's faces, on the output's vertices, before they go
    std::vector<uint32_t> input;
    input.reserve(3 * m.face.size());
    for (const Face& f : m.face)
      if (!f.IsD())
        for (int c = 0; c < 3; ++c)
          input.push_back(report.remap[vcg::tri::Index(m, f.cV(c))]);
    doc.polygons = doc.polygons.surviving(report, input, simplified.triangles);
  }
  const vrs_vcg::CornerData data = doc.corner_data();
  const bool carry = data.any() && report.corner_source.size() == simplified.triangles.size();
  std::vector<size_t> live; // core face index -> index in m.face
  for (size_t f = 0; f < m.face.size(); ++f)
    if (!m.face[f].IsD()) live.push_back(f);
  std::vector<uint32_t> old_of(simplified.vertex_count());
  for (size_t v = 0; v < report.remap.size(); ++v) {
    if (report.remap[v] == vrs::kRemoved)
      vcg::tri::Allocator<VcgMesh>::DeleteVertex(m, m.vert[v]);
    else
      old_of[report.remap[v]] = static_cast<uint32_t>(v);
  }
  for (Face& f : m.face)
    if (!f.IsD()) vcg::tri::Allocator<VcgMesh>::DeleteFace(m, f);
  auto fi = vcg::tri::Allocator<VcgMesh>::AddFaces(m, simplified.face_count());
  for (size_t t = 0; t < simplified.face_count(); ++t, ++fi)
    for (int c = 0; c < 3; ++c) {
      fi->V(c) = &m.vert[old_of[simplified.triangles[3 * t + c]]];
      if (carry) {
        const uint32_t source = report.corner_source[3 * t + c];
        vrs_vcg::copy_corner(data, m.face[live[source / 3]], int(source % 3), *fi, c, c == 0);
      }
      if (carry && c == 2 && report.face_source[t] == vrs::kRemoved)
        vrs_vcg::finish_face(data, *fi);
    }
  // Without corner sources the new faces have no per-corner data to write.
  if (!carry)
    doc.mask &= ~(vcg::tri::io::Mask::IOM_WEDGTEXCOORD | vcg::tri::io::Mask::IOM_WEDGNORMAL |
                  vcg::tri::io::Mask::IOM_FACECOLOR);
  vcg::tri::Allocator<VcgMesh>::CompactEveryVector(m);
  vcg::tri::UpdateBounding<VcgMesh>::Box(m);
}

namespace {

// The exporter's own message on failure, empty on success.
std::string write_as(VcgDocument& doc, const std::string& path, bool ascii) {
  using vcg::tri::io::Mask;
  int mask = doc.mask & (Mask::IOM_VERTCOORD | Mask::IOM_VERTNORMAL | Mask::IOM_VERTCOLOR |
                         Mask::IOM_VERTQUALITY | Mask::IOM_VERTTEXCOORD | Mask::IOM_VERTFLAGS |
                         Mask::IOM_WEDGTEXCOORD | Mask::IOM_WEDGNORMAL | Mask::IOM_FACECOLOR);
  if (ends_with(path, ".ply")) {
    const int err = vcg::tri::io::ExporterPLY<VcgMesh>::Save(doc.mesh, path.c_str(), mask, !ascii);
    return err ? vcg::tri::io::ExporterPLY<VcgMesh>::ErrorMsg(err) : "";
  }
  if (ends_with(path, ".obj")) return write_obj(path, doc);
  if (ends_with(path, ".off")) return write_off(path, doc, mask);
  const int err = vcg::tri::io::Exporter<VcgMesh>::Save(doc.mesh, path.c_str(), mask);
  return err ? vcg::tri::io::Exporter<VcgMesh>::ErrorMsg(err) : "";
}

} // namespace

std::string save(VcgDocument& doc, const std::string& path, bool ascii, const ExactVertices* exact,
                 const std::vector<uint32_t>* kept) {
  // Under a temporary name beside the output (same extension: it picks the format), renamed
  // once whole, with Ctrl-C and kill held meanwhile: a failed or interrupted write never leaves
  // a half-written file, under either name.
  const size_t slash = path.rfind('/');
  const std::string tmp = path.substr(0, slash + 1) + ".vrsimplify-" + std::to_string(getpid()) +
                          "-" + path.substr(slash + 1);
  sigset_t hold, before;
  sigemptyset(&hold);
  for (int sig : {SIGINT, SIGTERM, SIGHUP})
    sigaddset(&hold, sig);
  sigprocmask(SIG_BLOCK, &hold, &before);
  std::string err = write_as(doc, tmp, ascii);
  if (err.empty() && exact && kept && exact->needed()) {
    const std::string vertices = tmp + ".exact";
    err = exact->rewrite(tmp, vertices, *kept);
    std::remove(tmp.c_str());
    if (err.empty() && std::rename(vertices.c_str(), path.c_str()) != 0) err = std::strerror(errno);
    std::remove(vertices.c_str());
  } else if (err.empty() && std::rename(tmp.c_str(), path.c_str()) != 0) {
    err = std::strerror(errno);
  }
  if (!err.empty()) std::remove(tmp.c_str());
  sigprocmask(SIG_SETMASK, &before, nullptr);
  return err.empty() ? err : "cannot write " + path + ": " + err;
}

} // namespace vrs_tool
