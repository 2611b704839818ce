#include "mesh_stream.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace vrs::tiled {

namespace {

bool ends_with(std::string s, const std::string& suffix) {
  for (char& c : s)
    c = char(std::tolower((unsigned char)c));
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool read_line(std::FILE* in, std::string& line) {
  line.clear();
  int c;
  while ((c = getc_unlocked(in)) != EOF) {
    if (c == '\n') return true;
    if (c != '\r') line.push_back(char(c));
    if (line.size() > (1u << 20)) return false; // no text line of a mesh is a megabyte long
  }
  return !line.empty();
}

// ---- PLY ---------------------------------------------------------------------------------

enum class Type : uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64, Bad };

Type type_of(const std::string& t) {
  if (t == "char" || t == "int8") return Type::Int8;
  if (t == "uchar" || t == "uint8") return Type::UInt8;
  if (t == "short" || t == "int16") return Type::Int16;
  if (t == "ushort" || t == "uint16") return Type::UInt16;
  if (t == "int" || t == "int32") return Type::Int32;
  if (t == "uint" || t == "uint32") return Type::UInt32;
  if (t == "float" || t == "float32") return Type::Float32;
  if (t == "double" || t == "float64") return Type::Float64;
  return Type::Bad;
}

size_t size_of(Type t) {
  static const size_t sizes[] = {1, 1, 2, 2, 4, 4, 4, 8, 0};
  return sizes[size_t(t)];
}

// A binary value in the machine's byte order (memcpy: the bytes need not be aligned).
template <class T> double load(const unsigned char* b) {
  T v;
  std::memcpy(&v, b, sizeof v);
  return double(v);
}

struct Property {
  std::string name;
  Type type = Type::Bad;
  bool list = false;
  Type count_type = Type::Bad;
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> props;
};

enum class Encoding { Ascii, Little, Big };

struct PlyReader {
  std::FILE* in;
  Encoding enc;
  std::string token_line; // ascii: the current line's remaining tokens
  size_t token_pos = 0;
  bool failed = false;
  // Binary values come out of this buffer, not a stdio call each (a quarter of the streaming
  // pass went to fread's locking and calls).
  std::vector<unsigned char> buf = std::vector<unsigned char>(size_t(1) << 16);
  size_t pos = 0, len = 0;

  bool take(unsigned char* b, size_t n) {
    if (len - pos < n) {
      std::memmove(buf.data(), buf.data() + pos, len - pos);
      len -= pos;
      pos = 0;
      len += std::fread(buf.data() + len, 1, buf.size() - len, in);
      if (len < n) return false;
    }
    std::memcpy(b, buf.data() + pos, n);
    pos += n;
    return true;
  }

  bool next_token(std::string& tok) {
    for (;;) {
      while (token_pos < token_line.size() && std::isspace((unsigned char)token_line[token_pos]))
        ++token_pos;
      if (token_pos < token_line.size()) break;
      if (!read_line(in, token_line)) return false;
      token_pos = 0;
    }
    size_t start = token_pos;
    while (token_pos < token_line.size() && !std::isspace((unsigned char)token_line[token_pos]))
      ++token_pos;
    tok.assign(token_line, start, token_pos - start);
    return true;
  }

  // One value of type t as a double; false on a truncated or malformed file.
  bool value(Type t, double& out) {
    if (enc == Encoding::Ascii) {
      std::string tok;
      if (!next_token(tok)) return false;
      char* end = nullptr;
      out = std::strtod(tok.c_str(), &end);
      return end && *end == '\0';
    }
    unsigned char b[8];
    const size_t n = size_of(t);
    if (!take(b, n)) return false;
    const bool swap = (enc == Encoding::Big) != (__BYTE_ORDER__ == __ORDER_BIG_ENDIAN__);
    if (swap)
      for (size_t i = 0; i < n / 2; ++i)
        std::swap(b[i], b[n - 1 - i]);
    switch (t) {
    case Type::Int8: out = double(int8_t(b[0])); break;
    case Type::UInt8: out = double(b[0]); break;
    case Type::Int16: out = load<int16_t>(b); break;
    case Type::UInt16: out = load<uint16_t>(b); break;
    case Type::Int32: out = load<int32_t>(b); break;
    case Type::UInt32: out = load<uint32_t>(b); break;
    case Type::Float32: out = load<float>(b); break;
    case Type::Float64: out = load<double>(b); break;
    default: return false;
    }
    return true;
  }
};

std::string read_ply(std::FILE* in, const StreamSink& sink) {
  std::string line;
  if (!read_line(in, line) || line != "ply") return "not a PLY file";
  Encoding enc = Encoding::Ascii;
  std::vector<Element> elements;
  bool format = false;
  for (;;) {
    if (!read_line(in, line)) return "truncated PLY header";
    char word[64] = {0}, a[64] = {0}, b[64] = {0}, c[64] = {0}, d[64] = {0};
    const int n = std::sscanf(line.c_str(), "%63s %63s %63s %63s %63s", word, a, b, c, d);
    const std::string w = n > 0 ? word : "";
    if (w == "end_header") break;
    if (w == "format") {
      const std::string f = a;
      enc = f == "ascii"                  ? Encoding::Ascii
            : f == "binary_little_endian" ? Encoding::Little
            : f == "binary_big_endian"    ? Encoding::Big
                                          : Encoding(-1);
      if (int(enc) < 0) return "unknown PLY format " + f;
      format = true;
    } else if (w == "element") {
      char* end = nullptr;
      Element e;
      e.name = a;
      e.count = std::strtoull(b, &end, 10);
      if (n < 3 || !end || *end || b[0] == '-') return "bad PLY element line: " + line;
      elements.push_back(e);
    } else if (w == "property") {
      if (elements.empty()) return "PLY property before any element";
      Property p;
      if (std::string(a) == "list") {
        p.list = true;
        p.count_type = type_of(b);
        p.type = type_of(c);
        p.name = d;
        if (n < 5 || p.count_type == Type::Bad || p.count_type == Type::Float32 ||
            p.count_type == Type::Float64 || p.type == Type::Bad)
          return "bad PLY list property: " + line;
      } else {
        p.type = type_of(a);
        p.name = b;
        if (n < 3 || p.type == Type::Bad) return "bad PLY property: " + line;
      }
      elements.back().props.push_back(p);
    } else if (w != "comment" && w != "obj_info" && !w.empty()) {
      return "unknown PLY header line: " + line;
    }
  }
  if (!format) return "PLY header without a format line";
  PlyReader r{in, enc, "", 0, false};
  uint64_t vertices_read = 0;
  for (const Element& e : elements) {
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    int xyz[3] = {-1, -1, -1}, indices = -1;
    for (size_t i = 0; i < e.props.size(); ++i) {
      const Property& p = e.props[i];
      if (is_vertex && !p.list && (p.name == "x" || p.name == "y" || p.name == "z"))
        xyz[p.name[0] - 'x'] = int(i);
      if (is_face && p.list && (p.name == "vertex_indices" || p.name == "vertex_index"))
        indices = int(i);
    }
    if (is_vertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0))
      return "PLY vertices without x, y and z";
    if (is_face && indices < 0) return "PLY faces without vertex_indices";
    std::vector<int64_t> poly;
    if (e.props.empty()) continue; // nothing to read, however many it claims
    for (uint64_t k = 0; k < e.count; ++k) {
      float p3[3] = {0, 0, 0};
      for (size_t i = 0; i < e.props.size(); ++i) {
        const Property& p = e.props[i];
        double v;
        if (!p.list) {
          if (!r.value(p.type, v))
            return "truncated or malformed PLY " + e.name + " " + std::to_string(k);
          for (int a = 0; a < 3; ++a)
            if (int(i) == xyz[a]) p3[a] = float(v);
          continue;
        }
        double count;
        if (!r.value(p.count_type, count) || count < 0 || count > 1e6)
          return "truncated or malformed PLY " + e.name + " " + std::to_string(k);
        if (int(i) == indices) poly.clear();
        for (int64_t j = 0; j < int64_t(count); ++j) {
          if (!r.value(p.type, v))
            return "truncated or malformed PLY " + e.name + " " + std::to_string(k);
          if (int(i) != indices) continue;
          if (!(std::fabs(v) < 9e18)) // a float list's NaN or 1e37 is no index (nor an int64)
            return "malformed PLY " + e.name + " " + std::to_string(k) + ": vertex index " +
                   std::to_string(v);
          poly.push_back(int64_t(v));
        }
      }
      if (is_vertex) {
        sink.vertex(p3);
        ++vertices_read;
      } else if (is_face) {
        for (size_t j = 2; j < poly.size(); ++j) {
          const int64_t t[3] = {poly[0], poly[j - 1], poly[j]};
          sink.triangle(t);
        }
      }
    }
  }
  (void)vertices_read;
  return {};
}

// ---- OBJ ---------------------------------------------------------------------------------

std::string read_obj(std::FILE* in, const StreamSink& sink) {
  std::string line;
  uint64_t line_no = 0, vertices = 0;
  std::vector<int64_t> poly;
  while (read_line(in, line)) {
    ++line_no;
    const char* s = line.c_str();
    while (*s == ' ' || *s == '\t')
      ++s;
    if (s[0] == 'v' && (s[1] == ' ' || s[1] == '\t')) {
      float p[3];
      char* end = const_cast<char*>(s + 1);
      for (float& c : p) {
        char* start = end;
        c = std::strtof(start, &end);
        if (end == start) return "line " + std::to_string(line_no) + ": bad vertex";
      }
      sink.vertex(p);
      ++vertices;
    } else if (s[0] == 'f' && (s[1] == ' ' || s[1] == '\t')) {
      poly.clear();
      const char* c = s + 1;
      for (;;) {
        while (*c == ' ' || *c == '\t')
          ++c;
        if (!*c) break;
        char* end = nullptr;
        long long i = std::strtoll(c, &end, 10);
        if (end == c || i == 0) return "line " + std::to_string(line_no) + ": bad face";
        poly.push_back(i > 0 ? int64_t(i) - 1 : int64_t(vertices) + i);
        c = end;
        while (*c && *c != ' ' && *c != '\t')
          ++c; // skip /vt/vn
      }
      if (poly.size() < 3)
        return "line " + std::to_string(line_no) + ": face with fewer than 3 corners";
      for (size_t j = 2; j < poly.size(); ++j) {
        const int64_t t[3] = {poly[0], poly[j - 1], poly[j]};
        sink.triangle(t);
      }
    }
  }
  if (std::ferror(in)) return "read error";
  return {};
}

// ---- OFF (ascii) -------------------------------------------------------------------------

std::string read_off(std::FILE* in, const StreamSink& sink) {
  PlyReader r{in, Encoding::Ascii, "", 0, false}; // its ascii tokenizer, comments dropped below
  std::string tok;
  auto number = [&](double& v) {
    for (;;) {
      if (!r.next_token(tok)) return false;
      if (tok[0] != '#') break;
      r.token_pos = r.token_line.size(); // a comment runs to the end of its line
    }
    char* end = nullptr;
    v = std::strtod(tok.c_str(), &end);
    return end && *end == '\0';
  };
  if (!r.next_token(tok) || (tok != "OFF" && tok != "COFF" && tok != "NOFF"))
    return "not an ascii OFF file";
  double nv, nf, ne;
  if (!number(nv) || !number(nf) || !number(ne) || nv < 0 || nf < 0 || nv > 4e9 || nf > 4e9)
    return "bad OFF counts";
  const size_t extra = tok == "COFF" ? 4 : 0; // per-vertex colors after x y z
  std::vector<int64_t> poly;
  for (double i = 0; i < nv; ++i) {
    double p[3];
    for (double& c : p)
      if (!number(c)) return "truncated or malformed OFF vertex " + std::to_string(int64_t(i));
    r.token_pos = r.token_line.size(); // colors, normals: the rest of the line
    (void)extra;
    const float f[3] = {float(p[0]), float(p[1]), float(p[2])};
    sink.vertex(f);
  }
  for (double i = 0; i < nf; ++i) {
    double k, v;
    if (!number(k) || k < 3 || k > 1e6)
      return "truncated or malformed OFF face " + std::to_string(int64_t(i));
    poly.clear();
    for (int j = 0; j < int(k); ++j) {
      if (!number(v)) return "truncated or malformed OFF face " + std::to_string(int64_t(i));
      poly.push_back(int64_t(v));
    }
    r.token_pos = r.token_line.size(); // a face color
    for (size_t j = 2; j < poly.size(); ++j) {
      const int64_t t[3] = {poly[0], poly[j - 1], poly[j]};
      sink.triangle(t);
    }
  }
  return {};
}

} // namespace

std::string read_mesh_stream(std::FILE* in, const std::string& name, const StreamSink& sink) {
  if (ends_with(name, ".ply")) return read_ply(in, sink);
  if (ends_with(name, ".obj")) return read_obj(in, sink);
  if (ends_with(name, ".off")) return read_off(in, sink);
  return "streamed input must be .ply, .obj or .off: " + name;
}

} // namespace vrs::tiled
