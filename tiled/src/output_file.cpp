#include "output_file.h"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "mesh_stream.h"
#include "tile_files.h"

namespace vrs::tiled {

namespace {

// A PLY face property CornerKeys::group packs: its type's size and how to print it.
struct Packed {
  size_t size = 0;
  char kind = 'u'; // 'i' signed, 'u' unsigned, 'f' float
};

Packed packed_of(const std::string& line) {
  char type[32] = {0};
  std::sscanf(line.c_str(), "property %31s", type);
  const std::string t = type;
  if (t == "char" || t == "int8") return {1, 'i'};
  if (t == "uchar" || t == "uint8") return {1, 'u'};
  if (t == "short" || t == "int16") return {2, 'i'};
  if (t == "ushort" || t == "uint16") return {2, 'u'};
  if (t == "int" || t == "int32") return {4, 'i'};
  if (t == "uint" || t == "uint32") return {4, 'u'};
  return {4, 'f'};
}

std::string dir_of(const std::string& path) {
  const size_t slash = path.rfind('/');
  return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
}

std::string real(const std::string& path) {
  char buf[PATH_MAX];
  return realpath(path.c_str(), buf) ? std::string(buf) : path;
}

// `target` (a path from `from_dir` or absolute) as a path relative to `to_dir`.
std::string relative_to(const std::string& target, const std::string& from_dir,
                        const std::string& to_dir) {
  if (!target.empty() && target[0] == '/') return target;
  const std::string a = real(from_dir), b = real(to_dir);
  if (a == b) return target;
  auto parts = [](const std::string& p) {
    std::vector<std::string> out;
    size_t i = 0;
    while (i < p.size()) {
      const size_t j = p.find('/', i);
      const std::string part = p.substr(i, j == std::string::npos ? std::string::npos : j - i);
      if (!part.empty()) out.push_back(part);
      if (j == std::string::npos) break;
      i = j + 1;
    }
    return out;
  };
  const std::vector<std::string> pa = parts(a), pb = parts(b);
  size_t common = 0;
  while (common < pa.size() && common < pb.size() && pa[common] == pb[common])
    ++common;
  std::string rel;
  for (size_t i = common; i < pb.size(); ++i)
    rel += "../";
  for (size_t i = common; i < pa.size(); ++i)
    rel += pa[i] + "/";
  return rel + target;
}

struct Writer {
  RecordWriter& out;
  void text(const std::string& s) { out.write(s.data(), s.size()); }
  void text(const char* s, size_t n) { out.write(s, n); }
  // A binary value of `n` bytes, in the file's byte order.
  void bytes(const void* p, size_t n, bool big) {
    unsigned char b[8];
    std::memcpy(b, p, n);
    if (big != (__BYTE_ORDER__ == __ORDER_BIG_ENDIAN__))
      for (size_t i = 0; i < n / 2; ++i)
        std::swap(b[i], b[n - 1 - i]);
    out.write(b, n);
  }
};

// A packed value as ascii PLY text: an integer of its size and sign, or a float (9 digits).
std::string value_text(const unsigned char* p, const Packed& t) {
  char buf[48];
  if (t.kind == 'f') {
    float f;
    std::memcpy(&f, p, 4);
    std::snprintf(buf, sizeof buf, "%.9g", double(f));
    return buf;
  }
  uint32_t raw = 0; // packed in this machine's order (little endian): the low bytes
  std::memcpy(&raw, p, t.size);
  const unsigned bits = 8 * unsigned(t.size);
  if (t.kind == 'i' && bits < 32 && (raw >> (bits - 1)) & 1) raw |= ~0u << bits; // sign-extend
  if (t.kind == 'i')
    std::snprintf(buf, sizeof buf, "%d", int32_t(raw));
  else
    std::snprintf(buf, sizeof buf, "%u", raw);
  return buf;
}

} // namespace

std::string format_of(const std::string& path) {
  const size_t dot = path.rfind('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return "";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext)
    c = char(std::tolower((unsigned char)c));
  return ext == "ply" || ext == "obj" || ext == "off" ? ext : "";
}

uint64_t write_output(const std::string& input, const std::string& output, uint64_t vertices,
                      uint64_t texcoords, uint64_t normals, bool flat_normals,
                      const std::vector<std::string>& materials, const FaceSource& faces,
                      const OutputPolygons* polygons) {
  const std::string format = format_of(input);
  if (format.empty() || format != format_of(output))
    throw std::runtime_error("a tiled run writes the input's format (" + format +
                             "): cannot write " + output);
  // Which vertices (and OBJ vt, vn lines) the faces still use, numbered in input order.
  std::vector<uint32_t> index(vertices, 0), vt(format == "obj" ? texcoords : 0),
      vn(format == "obj" && !flat_normals ? normals : 0);
  uint64_t face_count = 0;
  faces([&](const FaceRecord& r) {
    for (int c = 0; c < 3; ++c) {
      index[r.v[c]] = 1;
      if (r.a[c] && r.a[c] <= vt.size()) vt[r.a[c] - 1] = 1;
      if (r.b[c] && r.b[c] <= vn.size()) vn[r.b[c] - 1] = 1;
    }
    ++face_count;
  });
  const auto number = [](std::vector<uint32_t>& used) {
    uint32_t next = 0;
    for (uint32_t& i : used)
      if (i) i = ++next;
    return uint64_t(next);
  };
  const uint64_t used_vertices = number(index);
  number(vt);
  number(vn);

  RecordWriter file(output, /*durable=*/true);
  Writer out{file};
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(input.c_str(), "rb"), &std::fclose);
  if (!in) throw std::runtime_error("cannot read " + input + " again: " + std::strerror(errno));
  std::setvbuf(in.get(), nullptr, _IOFBF, 1 << 20);

  Layout layout;
  bool ascii = true, big = false;
  std::vector<Packed> packed;
  uint64_t k = 0, t = 0, n = 0; // the input's vertex, vt and vn being read
  StreamSink sink;
  sink.vertices_only = true;
  sink.layout = [&](const Layout& l) {
    layout = l;
    if (l.format == Layout::Format::Ply) {
      ascii = l.ply_format.find("ascii") != std::string::npos;
      big = l.ply_format.find("big") != std::string::npos;
      std::string h = "ply\n" + l.ply_format + "\ncomment vrsimplify, tiled\nelement vertex " +
                      std::to_string(used_vertices) + "\n";
      for (const std::string& p : l.vertex_properties)
        h += p + "\n";
      h += "element face " + std::to_string(face_count) + "\n";
      h += "property list uchar int vertex_indices\n";
      if (!l.texcoord.empty()) h += "property list uchar float texcoord\n";
      for (const std::string& p : l.face_properties) {
        h += p + "\n";
        packed.push_back(packed_of(p));
      }
      out.text(h + "end_header\n");
    } else if (l.format == Layout::Format::Off) {
      const uint64_t written = face_count - (polygons ? polygons->merged() : 0);
      out.text(l.off_keyword + "\n" + std::to_string(used_vertices) + " " +
               std::to_string(written) + " 0\n");
    } else {
      out.text("# vrsimplify, tiled\n");
    }
  };
  sink.vertex = [](const double*) {};
  sink.triangle = [](const int64_t*, const CornerKeys&) {};
  sink.raw_vertex = [&](const char* data, size_t size) {
    if (index[k++]) {
      out.text(data, size);
      if (ascii) out.text("\n", 1);
    }
  };
  const std::string in_dir = dir_of(input), out_dir = dir_of(output);
  sink.other_line = [&](const std::string& line) {
    const size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos) return;
    const char* s = line.c_str() + start;
    if (std::strncmp(s, "vt", 2) == 0 && (s[2] == ' ' || s[2] == '\t')) {
      if (t < vt.size() && vt[t++]) out.text(line + "\n");
    } else if (std::strncmp(s, "vn", 2) == 0 && (s[2] == ' ' || s[2] == '\t')) {
      if (n < vn.size() && vn[n++]) out.text(line + "\n");
    } else if (std::strncmp(s, "mtllib", 6) == 0 && (s[6] == ' ' || s[6] == '\t')) {
      // Each library named, valid from the output's folder (textures are named from the
      // library's own folder, so they stay valid too).
      std::string rewritten = "mtllib";
      const char* c = s + 6;
      for (;;) {
        while (*c == ' ' || *c == '\t')
          ++c;
        if (!*c) break;
        const char* e = c;
        while (*e && *e != ' ' && *e != '\t')
          ++e;
        rewritten += " " + relative_to(std::string(c, e), in_dir, out_dir);
        c = e;
      }
      out.text(rewritten + "\n");
    }
  };
  const std::string error = read_mesh_stream(in.get(), input, sink);
  if (!error.empty()) throw std::runtime_error("cannot read " + input + " again: " + error);

  uint32_t group = 0;
  uint64_t face_normals = 0;
  char line[256];
  // Polygons (OBJ, OFF): one face where their first triangle comes, none for the others.
  std::vector<uint8_t> done(polygons ? polygons->count() : 0, 0);
  faces([&](const FaceRecord& r) {
    const uint32_t polygon = polygons ? polygons->of(r) : OutputPolygons::kNone;
    if (polygon != OutputPolygons::kNone) {
      if (done[polygon]) return;
      done[polygon] = 1;
    }
    // The face's corners: the triangle's, or its polygon's (vertex, vt key, vn key).
    const uint32_t corners = polygon == OutputPolygons::kNone ? 3 : polygons->corner_count(polygon);
    auto corner = [&](uint32_t k, uint32_t& v, uint32_t& a, uint32_t& b) {
      if (polygon == OutputPolygons::kNone)
        v = r.v[k], a = r.a[k], b = r.b[k];
      else
        v = polygons->vertex(polygon, k), a = polygons->key_a(polygon, k),
        b = polygons->key_b(polygon, k);
    };
    if (layout.format == Layout::Format::Obj) {
      if (r.group != group && r.group <= materials.size()) {
        group = r.group;
        out.text("usemtl " + materials[group - 1] + "\n");
      }
      if (flat_normals) { // the face's own unit normal, just before it
        const float* p = r.p[0];
        const float u[3] = {r.p[1][0] - p[0], r.p[1][1] - p[1], r.p[1][2] - p[2]},
                    w[3] = {r.p[2][0] - p[0], r.p[2][1] - p[1], r.p[2][2] - p[2]};
        float n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                      u[0] * w[1] - u[1] * w[0]};
        const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (length > 0)
          for (float& x : n)
            x /= length;
        const int len = std::snprintf(line, sizeof line, "vn %.9g %.9g %.9g\n", double(n[0]),
                                      double(n[1]), double(n[2]));
        out.text(line, size_t(len));
        ++face_normals;
      }
      std::string f = "f";
      for (uint32_t c = 0; c < corners; ++c) {
        uint32_t v, a, b;
        corner(c, v, a, b);
        int len = std::snprintf(line, sizeof line, " %u", index[v]);
        const bool has_vt = a && a <= vt.size();
        if (has_vt) len += std::snprintf(line + len, sizeof line - size_t(len), "/%u", vt[a - 1]);
        if (flat_normals)
          len += std::snprintf(line + len, sizeof line - size_t(len), "%s/%llu", has_vt ? "" : "/",
                               (unsigned long long)face_normals);
        else if (b && b <= vn.size())
          len += std::snprintf(line + len, sizeof line - size_t(len), "%s/%u", has_vt ? "" : "/",
                               vn[b - 1]);
        f.append(line, size_t(len));
      }
      out.text(f + "\n");
      return;
    }
    if (layout.format == Layout::Format::Off && polygon == OutputPolygons::kNone) {
      const int len = std::snprintf(line, sizeof line, "3 %u %u %u\n", index[r.v[0]] - 1,
                                    index[r.v[1]] - 1, index[r.v[2]] - 1);
      out.text(line, size_t(len));
      return;
    }
    if (layout.format == Layout::Format::Off) {
      std::string f = std::to_string(corners);
      for (uint32_t c = 0; c < corners; ++c) {
        uint32_t v, a, b;
        corner(c, v, a, b);
        f += " " + std::to_string(index[v] - 1);
      }
      out.text(f + "\n");
      return;
    }
    unsigned char group_bytes[4];
    std::memcpy(group_bytes, &r.group, 4);
    if (ascii) {
      std::string f = "3";
      for (int c = 0; c < 3; ++c)
        f += " " + std::to_string(index[r.v[c]] - 1);
      if (!layout.texcoord.empty()) {
        f += " 6";
        for (int c = 0; c < 3; ++c)
          for (const uint32_t bits : {r.a[c], r.b[c]})
            f += " " + value_text(reinterpret_cast<const unsigned char*>(&bits), {4, 'f'});
      }
      size_t at = 0;
      for (const Packed& p : packed) {
        f += " " + value_text(group_bytes + at, p);
        at += p.size;
      }
      out.text(f + "\n");
      return;
    }
    const uint8_t three = 3, six = 6;
    out.text(reinterpret_cast<const char*>(&three), 1);
    for (int c = 0; c < 3; ++c) {
      const int32_t i = int32_t(index[r.v[c]] - 1);
      out.bytes(&i, 4, big);
    }
    if (!layout.texcoord.empty()) {
      out.text(reinterpret_cast<const char*>(&six), 1);
      for (int c = 0; c < 3; ++c) {
        out.bytes(&r.a[c], 4, big);
        out.bytes(&r.b[c], 4, big);
      }
    }
    size_t at = 0;
    for (const Packed& p : packed) {
      out.bytes(group_bytes + at, p.size, big);
      at += p.size;
    }
  });
  file.commit();
  return face_count;
}

} // namespace vrs::tiled
