// File readers and writers of our own, for the formats whose vcglib 2020.09 code is broken.
// Readers:
// - OBJ: every triangle that uses the file's first vertex is dropped (the importer checks the
//   1-based index after making it 0-based);
// - binary STL: the 80-byte header is read as a C string without a terminator (a stack
//   overflow that AddressSanitizer reports on any header without a NUL);
// - OFF: a line of blanks among the vertices makes it call strtol on a null pointer (a crash,
//   CGAL's prim.off), and a huge declared count is allocated before anything is checked.
// Writers:
// - OBJ: vcglib writes coordinates with 6 decimals, so kept vertices would not be the input's;
// - OFF: 7 digits, and its polygons name each corner by the vertex's flags, not its index.
// Both write the document's polygons whole.
#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "vcg_mesh.h"
#include <wrap/io_trimesh/io_mask.h>

namespace {

// Three coordinates as text, by strtof's grammar: "nan" and "inf" read as the PLY reader reads
// them (the core keeps such vertices and says so), not as a malformed file; istream's >> for
// float refuses them.
// One coordinate, the whole token [begin, end) or nothing.
bool coordinate(const char* begin, const char* end, float& c) {
  char* stop = nullptr;
  c = std::strtof(begin, &stop);
  return begin != end && stop == end;
}

bool read_xyz(std::istream& s, float& x, float& y, float& z) {
  for (float* c : {&x, &y, &z}) {
    std::string token;
    if (!(s >> token) || !coordinate(token.c_str(), token.c_str() + token.size(), *c)) return false;
  }
  return true;
}

// One line's numbers read in place, as the stream operators read them (an istringstream a line
// was a visible share of a large OFF's run): xyz() by read_xyz's grammar, whole tokens;
// integer() and real() as >> for long and float: leading blanks skipped, the longest number
// there taken, the rest left for the next read.
class LineNumbers {
 public:
  explicit LineNumbers(const std::string& line) : p_(line.c_str()) {}
  bool xyz(float& x, float& y, float& z) {
    for (float* c : {&x, &y, &z}) {
      skip_blanks();
      const char* token = p_;
      while (*p_ && !std::isspace(static_cast<unsigned char>(*p_)))
        ++p_;
      if (!coordinate(token, p_, *c)) return false;
    }
    return true;
  }
  bool integer(long& v) {
    skip_blanks();
    if (!*p_ || !(std::isdigit(static_cast<unsigned char>(*p_)) || *p_ == '-' || *p_ == '+'))
      return false;
    char* end = nullptr;
    errno = 0;
    v = std::strtol(p_, &end, 10);
    if (end == p_ || errno == ERANGE) return false;
    p_ = end;
    return true;
  }
  bool real(float& v) {
    skip_blanks();
    // As >> reads a float: digits, a point, an exponent (no "nan", "inf" or hex).
    const char* q = p_;
    if (*q == '-' || *q == '+') ++q;
    if (!(std::isdigit(static_cast<unsigned char>(*q)) ||
          (*q == '.' && std::isdigit(static_cast<unsigned char>(q[1])))))
      return false;
    char* end = nullptr;
    v = std::strtof(p_, &end);
    if (end == p_) return false;
    p_ = end;
    return true;
  }

 private:
  void skip_blanks() {
    while (*p_ && std::isspace(static_cast<unsigned char>(*p_)))
      ++p_;
  }
  const char* p_;
};

} // namespace

namespace vrs_tool {

namespace {

void fill(VcgDocument& doc, const std::vector<vcg::Point3f>& pos,
          const std::vector<vcg::Color4b>& color, const std::vector<int>& tris) {
  VcgMesh& m = doc.mesh;
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
}

// An OBJ corner "v", "v/t", "v/t/n" or "v//n" as 0-based indices (-1 when absent); false when
// an index is 0 or names nothing.
bool parse_corner(const std::string& corner, size_t nv, size_t nt, size_t nn, long out[3]) {
  const size_t sizes[3] = {nv, nt, nn};
  size_t at = 0;
  for (int k = 0; k < 3; ++k) {
    out[k] = -1;
    if (at > corner.size()) continue;
    size_t end = corner.find('/', at);
    std::string part = corner.substr(at, end == std::string::npos ? std::string::npos : end - at);
    at = end == std::string::npos ? corner.size() + 1 : end + 1;
    if (part.empty()) {
      if (k == 0) return false;
      continue;
    }
    long i = std::strtol(part.c_str(), nullptr, 10);
    long idx = i > 0 ? i - 1 : long(sizes[k]) + i;
    if (i == 0 || idx < 0 || idx >= long(sizes[k])) return false;
    out[k] = idx;
  }
  return true;
}

} // namespace

// Positions, faces (polygons fanned, negative indices relative) with the common
// "v x y z r g b" colour extension, and the faces' per-corner texture coordinates ("vt") and
// normals ("vn"), kept per corner as the file gives them.
std::string read_obj(const std::string& path, VcgDocument& doc) {
  std::ifstream in(path);
  if (!in) return "cannot open file";
  VcgMesh& m = doc.mesh;
  std::vector<vcg::Point3f> pos, normals;
  std::vector<vcg::Point2f> uvs;
  std::vector<vcg::Color4b> color;
  std::vector<int> tris;
  std::vector<long> corner_uv, corner_normal; // per triangle corner, -1 when absent
  std::vector<short> face_material;           // per triangle: index into doc.materials
  short material = 0;
  std::string line;
  size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      float x, y, z, r, g, b;
      if (!read_xyz(s, x, y, z)) return "bad vertex on line " + std::to_string(line_no);
      pos.emplace_back(x, y, z);
      if (s >> r >> g >> b) color.emplace_back(vcg::Color4b(r * 255, g * 255, b * 255, 255));
    } else if (tag == "vt") {
      float u, v = 0;
      if (!(s >> u)) return "bad texture coordinate on line " + std::to_string(line_no);
      s >> v;
      uvs.emplace_back(u, v);
    } else if (tag == "mtllib") {
      std::getline(s >> std::ws, doc.material_library);
    } else if (tag == "usemtl") {
      std::string name;
      std::getline(s >> std::ws, name);
      auto it = std::find(doc.materials.begin(), doc.materials.end(), name);
      material = short(it - doc.materials.begin());
      if (it == doc.materials.end()) doc.materials.push_back(name);
    } else if (tag == "vn") {
      float x, y, z;
      if (!(s >> x >> y >> z)) return "bad normal on line " + std::to_string(line_no);
      normals.emplace_back(x, y, z);
    } else if (tag == "f") {
      std::vector<std::array<long, 3>> poly;
      std::string corner;
      while (s >> corner) {
        std::array<long, 3> c;
        if (!parse_corner(corner, pos.size(), uvs.size(), normals.size(), c.data()))
          return "face on line " + std::to_string(line_no) + " names a missing vertex";
        poly.push_back(c);
      }
      if (poly.size() > 3) doc.polygons.add_fan(uint32_t(tris.size() / 3), uint32_t(poly.size()));
      for (size_t j = 1; j + 1 < poly.size(); ++j) {
        face_material.push_back(material);
        for (size_t k : {size_t(0), j, j + 1}) {
          tris.push_back(int(poly[k][0]));
          corner_uv.push_back(poly[k][1]);
          corner_normal.push_back(poly[k][2]);
        }
      }
    }
  }
  fill(doc, pos, color, tris);
  const bool has_uv =
      std::any_of(corner_uv.begin(), corner_uv.end(), [](long i) { return i >= 0; });
  const bool has_n =
      std::any_of(corner_normal.begin(), corner_normal.end(), [](long i) { return i >= 0; });
  using vcg::tri::io::Mask;
  doc.enable((has_uv ? Mask::IOM_WEDGTEXCOORD : 0) | (has_n ? Mask::IOM_WEDGNORMAL : 0));
  doc.mask |= (has_uv ? Mask::IOM_WEDGTEXCOORD : 0) | (has_n ? Mask::IOM_WEDGNORMAL : 0);
  for (size_t c = 0; c < tris.size() && (has_uv || has_n); ++c) {
    Face& f = m.face[c / 3];
    if (has_uv) {
      long t = corner_uv[c];
      f.WT(c % 3).U() = t >= 0 ? uvs[t].X() : 0.0f;
      f.WT(c % 3).V() = t >= 0 ? uvs[t].Y() : 0.0f;
      f.WT(c % 3).N() = face_material[c / 3];
    }
    if (has_n)
      f.WN(c % 3) = corner_normal[c] >= 0 ? normals[corner_normal[c]] : vcg::Point3f(0, 0, 0);
  }
  return {};
}

// Binary or ascii STL as a triangle soup (three new vertices per face, merged by the caller).
std::string read_stl(const std::string& path, VcgDocument& doc) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "cannot open file";
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<vcg::Point3f> pos;
  std::vector<int> tris;
  uint32_t count = 0;
  if (data.size() >= 84) std::memcpy(&count, data.data() + 80, 4);
  if (data.size() >= 84 && data.size() == 84 + 50 * size_t(count)) {
    for (size_t t = 0; t < count; ++t) {
      const char* rec = data.data() + 84 + 50 * t + 12; // skip the normal
      for (int c = 0; c < 3; ++c) {
        float p[3];
        std::memcpy(p, rec + 12 * c, 12);
        tris.push_back(int(pos.size()));
        pos.emplace_back(p[0], p[1], p[2]);
      }
    }
  } else if (data.compare(0, 5, "solid") == 0) {
    std::istringstream s(data);
    std::string word;
    while (s >> word) {
      if (word != "vertex") continue;
      float x, y, z;
      if (!read_xyz(s, x, y, z)) return "bad vertex in ascii STL";
      tris.push_back(int(pos.size()));
      pos.emplace_back(x, y, z);
    }
    if (tris.size() % 3) return "ascii STL with an incomplete facet";
  } else {
    return "neither binary (size does not match the face count) nor ascii STL";
  }
  fill(doc, pos, {}, tris);
  return {};
}

// OFF, COFF, NOFF, CNOFF, STOFF...: positions, optional per-vertex colours (0..255 integers
// or 0..1 floats), polygons fanned. Comments and blank lines anywhere; counts checked against
// what the file holds before anything is allocated.
std::string read_off(const std::string& path, VcgDocument& doc) {
  std::ifstream in(path);
  if (!in) return "cannot open file";
  std::vector<std::string> lines; // non-empty, comments stripped
  for (std::string line; std::getline(in, line);) {
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line);
  }
  if (lines.empty()) return "empty file";
  std::istringstream head(lines[0]);
  std::string magic;
  head >> magic;
  if (magic.size() < 3 || magic.compare(magic.size() - 3, 3, "OFF") != 0) return "no OFF header";
  const bool normals = magic.find('N') != std::string::npos;
  const bool colors = magic.find('C') != std::string::npos;
  const bool texcoords = magic.find("ST") != std::string::npos;
  if (magic.find_first_of("4n") != std::string::npos) return "only 3D OFF files are read";
  size_t line = 1;
  long nv = -1, nf = -1;
  if (!(head >> nv >> nf)) { // counts on their own line
    if (lines.size() < 2) return "no vertex and face counts";
    std::istringstream counts(lines[line++]);
    if (!(counts >> nv >> nf)) return "no vertex and face counts";
  }
  if (nv < 0 || nf < 0) return "negative counts";
  if (size_t(nv) + size_t(nf) > lines.size() - line)
    return "declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
           " faces, but holds " + std::to_string(lines.size() - line) + " lines";
  std::vector<vcg::Point3f> pos;
  std::vector<vcg::Color4b> color;
  std::vector<int> tris;
  pos.reserve(size_t(nv));
  for (long v = 0; v < nv; ++v, ++line) {
    LineNumbers s(lines[line]);
    float x, y, z, skip;
    if (!s.xyz(x, y, z)) return "bad vertex " + std::to_string(v);
    pos.emplace_back(x, y, z);
    // In the order the format gives them: normal, colour, texture coordinates.
    if (normals) s.real(skip) && s.real(skip) && s.real(skip);
    if (colors) {
      float c[4] = {0, 0, 0, 255};
      int k = 0;
      while (k < 4 && s.real(c[k]))
        ++k;
      if (k < 3) return "vertex " + std::to_string(v) + " lacks its colour";
      const bool unit = c[0] <= 1 && c[1] <= 1 && c[2] <= 1 && (k < 4 || c[3] <= 1);
      auto byte = [&](float f) {
        return uint8_t(std::min(255.0f, std::max(0.0f, unit ? f * 255 : f)));
      };
      color.emplace_back(byte(c[0]), byte(c[1]), byte(c[2]), k == 4 ? byte(c[3]) : 255);
    }
    if (texcoords) s.real(skip) && s.real(skip);
  }
  std::vector<int> poly;
  for (long f = 0; f < nf; ++f, ++line) {
    LineNumbers s(lines[line]);
    long n = 0;
    if (!s.integer(n) || n < 1 || n > 1000000) return "bad face " + std::to_string(f);
    poly.clear();
    for (long k = 0; k < n; ++k) {
      long i = -1;
      if (!s.integer(i)) return "face " + std::to_string(f) + " lists fewer corners than it says";
      if (i < 0 || i >= nv) return "face " + std::to_string(f) + " names a missing vertex";
      poly.push_back(int(i));
    }
    if (poly.size() > 3) doc.polygons.add_fan(uint32_t(tris.size() / 3), uint32_t(poly.size()));
    for (size_t j = 1; j + 1 < poly.size(); ++j)
      tris.insert(tris.end(), {poly[0], poly[j], poly[j + 1]});
  }
  fill(doc, pos, colors ? color : std::vector<vcg::Color4b>{}, tris);
  return {};
}

// Positions (and vertex colors) to 9 significant digits, which round-trip a float exactly;
// per-corner texture coordinates and normals as "vt"/"vn" with one entry per distinct value.
std::string write_obj(const std::string& path, const VcgDocument& doc) {
  std::ofstream out(path);
  if (!out) return "cannot open for writing";
  const VcgMesh& m = doc.mesh;
  const vrs_vcg::CornerData d = doc.corner_data();
  const bool colors = doc.mask & vcg::tri::io::Mask::IOM_VERTCOLOR;
  char buf[128];
  if (!doc.material_library.empty()) out << "mtllib " << doc.material_library << '\n';
  std::vector<int> index(m.vert.size(), -1);
  int next = 0;
  for (size_t v = 0; v < m.vert.size(); ++v) {
    if (m.vert[v].IsD()) continue;
    index[v] = ++next;
    const auto& p = m.vert[v].cP();
    int n = std::snprintf(buf, sizeof buf, "v %.9g %.9g %.9g", p[0], p[1], p[2]);
    out.write(buf, n);
    if (colors) {
      const auto& c = m.vert[v].cC();
      n = std::snprintf(buf, sizeof buf, " %.9g %.9g %.9g", c[0] / 255.0, c[1] / 255.0,
                        c[2] / 255.0);
      out.write(buf, n);
    }
    out << '\n';
  }
  // One "vt"/"vn" line per distinct value, in the order the faces use them.
  std::map<std::pair<float, float>, int> uv_index;
  std::map<std::array<float, 3>, int> n_index;
  std::vector<std::array<int, 3>> uv_of, n_of;
  for (const Face& f : m.face) {
    if (f.IsD()) continue;
    std::array<int, 3> uv{}, nn{};
    for (int c = 0; c < 3; ++c) {
      if (d.texcoord) {
        auto key = std::make_pair(f.cWT(c).U(), f.cWT(c).V());
        auto it = uv_index.emplace(key, int(uv_index.size()) + 1);
        if (it.second)
          out.write(buf, std::snprintf(buf, sizeof buf, "vt %.9g %.9g\n", key.first, key.second));
        uv[c] = it.first->second;
      }
      if (d.normal) {
        std::array<float, 3> key{f.cWN(c)[0], f.cWN(c)[1], f.cWN(c)[2]};
        auto it = n_index.emplace(key, int(n_index.size()) + 1);
        if (it.second)
          out.write(buf,
                    std::snprintf(buf, sizeof buf, "vn %.9g %.9g %.9g\n", key[0], key[1], key[2]));
        nn[c] = it.first->second;
      }
    }
    uv_of.push_back(uv);
    n_of.push_back(nn);
  }
  // The faces in order, each polygon whole where its first triangle comes (the faces are live:
  // the i-th face is m.face[i]).
  int material = -1;
  auto corner = [&](size_t i, int c) {
    out << ' ' << index[vcg::tri::Index(m, m.face[i].cV(c))];
    if (d.texcoord || d.normal) out << '/';
    if (d.texcoord) out << uv_of[i][size_t(c)];
    if (d.normal) out << '/' << n_of[i][size_t(c)];
  };
  for (size_t i = 0; i < uv_of.size(); ++i) {
    const Face& f = m.face[i];
    const uint32_t p = doc.polygons.of(uint32_t(i));
    if (p != Polygons::kNone && doc.polygons.corners(p)[0] / 3 != i) continue; // written
    const int mat = d.texcoord ? f.cWT(0).N() : 0;
    if (mat != material && mat >= 0 && size_t(mat) < doc.materials.size())
      out << "usemtl " << doc.materials[size_t(material = mat)] << '\n';
    out << 'f';
    if (p == Polygons::kNone) {
      for (int c = 0; c < 3; ++c)
        corner(i, c);
    } else {
      for (uint32_t k = 0; k < doc.polygons.corner_count(p); ++k)
        corner(doc.polygons.corners(p)[k] / 3, int(doc.polygons.corners(p)[k] % 3));
    }
    out << '\n';
  }
  return out ? std::string() : "write failed";
}

std::string write_off(const std::string& path, const VcgDocument& doc, int mask) {
  using vcg::tri::io::Mask;
  std::ofstream out(path);
  if (!out) return "cannot open for writing";
  const VcgMesh& m = doc.mesh;
  const bool normals = mask & Mask::IOM_VERTNORMAL, colors = mask & Mask::IOM_VERTCOLOR,
             uvs = mask & Mask::IOM_VERTTEXCOORD,
             face_colors = (mask & Mask::IOM_FACECOLOR) && m.face.IsColorEnabled();
  size_t faces = 0;
  for (size_t i = 0; i < m.face.size(); ++i) {
    const uint32_t p = doc.polygons.of(uint32_t(i));
    faces += !m.face[i].IsD() && (p == Polygons::kNone || doc.polygons.corners(p)[0] / 3 == i);
  }
  size_t vertices = 0;
  std::vector<size_t> index(m.vert.size());
  for (size_t v = 0; v < m.vert.size(); ++v)
    if (!m.vert[v].IsD()) index[v] = vertices++;
  // The keyword, then the counts on a line of their own (ExactVertices reads them there).
  out << (uvs ? "ST" : "") << (colors ? "C" : "") << (normals ? "N" : "") << "OFF\n"
      << vertices << ' ' << faces << " 0\n";
  char buf[256];
  for (const Vertex& v : m.vert) {
    if (v.IsD()) continue;
    const auto& p = v.cP();
    int n = std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g", p[0], p[1], p[2]);
    if (normals)
      n += std::snprintf(buf + n, sizeof buf - size_t(n), " %.9g %.9g %.9g", v.cN()[0], v.cN()[1],
                         v.cN()[2]);
    if (colors)
      n += std::snprintf(buf + n, sizeof buf - size_t(n), " %d %d %d %d", v.cC()[0], v.cC()[1],
                         v.cC()[2], v.cC()[3]);
    if (uvs)
      n += std::snprintf(buf + n, sizeof buf - size_t(n), " %.9g %.9g", v.cT().U(), v.cT().V());
    out.write(buf, n);
    out << '\n';
  }
  for (size_t i = 0; i < m.face.size(); ++i) {
    const Face& f = m.face[i];
    if (f.IsD()) continue;
    const uint32_t p = doc.polygons.of(uint32_t(i));
    if (p == Polygons::kNone) {
      out << 3;
      for (int c = 0; c < 3; ++c)
        out << ' ' << index[vcg::tri::Index(m, f.cV(c))];
    } else if (doc.polygons.corners(p)[0] / 3 == i) {
      out << doc.polygons.corner_count(p);
      for (uint32_t k = 0; k < doc.polygons.corner_count(p); ++k) {
        const uint32_t x = doc.polygons.corners(p)[k];
        out << ' ' << index[vcg::tri::Index(m, m.face[x / 3].cV(int(x % 3)))];
      }
    } else {
      continue; // written with its polygon
    }
    if (face_colors) out << ' ' << int(f.cC()[0]) << ' ' << int(f.cC()[1]) << ' ' << int(f.cC()[2]);
    out << '\n';
  }
  return out ? std::string() : "write failed";
}

} // namespace vrs_tool
