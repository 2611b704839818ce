#include "mesh_stream.h"

#include <algorithm>
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
  std::string* capture = nullptr; // when set, what is read is appended (a raw vertex)

  bool take(unsigned char* b, size_t n) {
    if (len - pos < n) {
      std::memmove(buf.data(), buf.data() + pos, len - pos);
      len -= pos;
      pos = 0;
      len += std::fread(buf.data() + len, 1, buf.size() - len, in);
      if (len < n) return false;
    }
    std::memcpy(b, buf.data() + pos, n);
    if (capture) capture->append(reinterpret_cast<const char*>(b), n);
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
    if (capture) capture->append(capture->empty() ? "" : " ").append(tok);
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

template <class T> void put(unsigned char* out, double v) {
  const T x = T(v);
  std::memcpy(out, &x, sizeof x);
}

// Whether v converts to type t without overflow (a file's 4e21 in a uchar field is malformed,
// and converting it would be undefined).
bool fits(Type t, double v) {
  switch (t) {
  case Type::Int8: return v > -129 && v < 128;
  case Type::UInt8: return v > -1 && v < 256;
  case Type::Int16: return v > -32769 && v < 32768;
  case Type::UInt16: return v > -1 && v < 65536;
  case Type::Int32: return v > -2147483649.0 && v < 2147483648.0;
  case Type::UInt32: return v > -1 && v < 4294967296.0;
  default: return true; // a float takes any double (an overflow is inf, defined)
  }
}

// Packs a face property's value into `out` at `at` as its type (what CornerKeys::group holds).
void pack(Type t, double v, unsigned char* out, size_t at) {
  switch (t) {
  case Type::Int8: put<int8_t>(out + at, v); break;
  case Type::UInt8: put<uint8_t>(out + at, v); break;
  case Type::Int16: put<int16_t>(out + at, v); break;
  case Type::UInt16: put<uint16_t>(out + at, v); break;
  case Type::Int32: put<int32_t>(out + at, v); break;
  case Type::UInt32: put<uint32_t>(out + at, v); break;
  case Type::Float32: put<float>(out + at, v); break;
  default: break;
  }
}

std::string read_ply(std::FILE* in, const StreamSink& sink) {
  std::string line;
  if (!read_line(in, line) || line != "ply") return "not a PLY file";
  Encoding enc = Encoding::Ascii;
  std::vector<Element> elements;
  std::vector<std::vector<std::string>> prop_lines; // each element's property lines, verbatim
  Layout layout;
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
      layout.ply_format = line;
      format = true;
    } else if (w == "element") {
      char* end = nullptr;
      Element e;
      e.name = a;
      e.count = std::strtoull(b, &end, 10);
      if (n < 3 || !end || *end || b[0] == '-') return "bad PLY element line: " + line;
      elements.push_back(e);
      prop_lines.emplace_back();
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
      prop_lines.back().push_back(line);
    } else if (w != "comment" && w != "obj_info" && !w.empty()) {
      return "unknown PLY header line: " + line;
    }
  }
  if (!format) return "PLY header without a format line";

  // What an output in the same format repeats, and what CornerKeys cannot carry.
  std::string uncarried;
  for (size_t e = 0; e < elements.size(); ++e) {
    const Element& el = elements[e];
    if (el.name == "vertex") {
      layout.vertex_properties = prop_lines[e];
    } else if (el.name == "face") {
      size_t bytes = 0;
      for (size_t i = 0; i < el.props.size(); ++i) {
        const Property& p = el.props[i];
        if (p.list && (p.name == "vertex_indices" || p.name == "vertex_index")) continue;
        if (p.list && p.name == "texcoord" && p.type == Type::Float32 && layout.texcoord.empty()) {
          layout.texcoord = prop_lines[e][i];
          continue;
        }
        if (p.list || (bytes += size_of(p.type)) > 4) {
          if (uncarried.empty()) uncarried = "the face property '" + p.name + "'";
          continue;
        }
        layout.face_properties.push_back(prop_lines[e][i]);
      }
    } else if (el.count > 0 && uncarried.empty()) {
      uncarried = "the element '" + el.name + "'";
    }
  }
  if (sink.layout) sink.layout(layout);
  if (!uncarried.empty() && sink.uncarried) sink.uncarried(uncarried);

  PlyReader r{in, enc, "", 0, false};
  std::string raw;
  for (const Element& e : elements) {
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    int xyz[3] = {-1, -1, -1}, indices = -1, texcoord = -1;
    for (size_t i = 0; i < e.props.size(); ++i) {
      const Property& p = e.props[i];
      if (is_vertex && !p.list && (p.name == "x" || p.name == "y" || p.name == "z"))
        xyz[p.name[0] - 'x'] = int(i);
      if (is_face && p.list && (p.name == "vertex_indices" || p.name == "vertex_index"))
        indices = int(i);
      if (is_face && p.list && p.name == "texcoord" && p.type == Type::Float32 && texcoord < 0)
        texcoord = int(i);
    }
    if (is_vertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0))
      return "PLY vertices without x, y and z";
    if (is_face && indices < 0) return "PLY faces without vertex_indices";
    std::vector<int64_t> poly;
    std::vector<float> uv;
    if (e.props.empty()) continue; // nothing to read, however many it claims
    const bool capture = is_vertex && bool(sink.raw_vertex);
    for (uint64_t k = 0; k < e.count; ++k) {
      double p3[3] = {0, 0, 0};
      unsigned char packed[4] = {0, 0, 0, 0};
      size_t packed_at = 0;
      if (capture) raw.clear(), r.capture = &raw;
      for (size_t i = 0; i < e.props.size(); ++i) {
        const Property& p = e.props[i];
        double v;
        if (!p.list) {
          if (!r.value(p.type, v))
            return "truncated or malformed PLY " + e.name + " " + std::to_string(k);
          for (int a = 0; a < 3; ++a)
            if (int(i) == xyz[a]) p3[a] = v;
          if (is_face && packed_at + size_of(p.type) <= 4) {
            if (!fits(p.type, v))
              return "PLY face " + std::to_string(k) + ": a value of " + p.name +
                     " does not fit its type";
            pack(p.type, v, packed, packed_at);
            packed_at += size_of(p.type);
          }
          continue;
        }
        double count;
        if (!r.value(p.count_type, count) || count < 0 || count > 1e6)
          return "truncated or malformed PLY " + e.name + " " + std::to_string(k);
        if (int(i) == indices) poly.clear();
        if (int(i) == texcoord) uv.clear();
        for (int64_t j = 0; j < int64_t(count); ++j) {
          if (!r.value(p.type, v))
            return "truncated or malformed PLY " + e.name + " " + std::to_string(k);
          if (int(i) == texcoord) uv.push_back(float(v));
          if (int(i) != indices) continue;
          if (!(std::fabs(v) < 9e18)) // a float list's NaN or 1e37 is no index (nor an int64)
            return "malformed PLY " + e.name + " " + std::to_string(k) + ": vertex index " +
                   std::to_string(v);
          poly.push_back(int64_t(v));
        }
      }
      r.capture = nullptr;
      if (is_vertex) {
        sink.vertex(p3);
        if (capture) sink.raw_vertex(raw.data(), raw.size());
      } else if (is_face) {
        CornerKeys keys;
        std::memcpy(&keys.group, packed, 4);
        const bool uvs = texcoord >= 0 && uv.size() == 2 * poly.size();
        if (texcoord >= 0 && !uvs && uncarried.empty() && sink.uncarried) {
          uncarried = "face " + std::to_string(k) + "'s texcoord list (not two per corner)";
          sink.uncarried(uncarried);
        }
        if (poly.size() > 3 && sink.polygon) sink.polygon(poly.size());
        for (size_t j = 2; j < poly.size(); ++j) {
          const int64_t t[3] = {poly[0], poly[j - 1], poly[j]};
          const size_t corner[3] = {0, j - 1, j};
          if (uvs)
            for (int c = 0; c < 3; ++c) {
              std::memcpy(&keys.a[c], &uv[2 * corner[c]], 4);
              std::memcpy(&keys.b[c], &uv[2 * corner[c] + 1], 4);
            }
          sink.triangle(t, keys);
        }
      }
    }
    if (is_vertex && sink.vertices_only) return {};
  }
  return {};
}

// ---- OBJ ---------------------------------------------------------------------------------

// One index of an OBJ face corner ("12", "-3"): 0-based, relative ones resolved against
// `count` read so far; false when it is no index.
bool obj_index(const char*& c, uint64_t count, int64_t& out) {
  char* end = nullptr;
  const long long i = std::strtoll(c, &end, 10);
  if (end == c || i == 0) return false;
  out = i > 0 ? int64_t(i) - 1 : int64_t(count) + i;
  c = end;
  return true;
}

std::string read_obj(std::FILE* in, const StreamSink& sink) {
  if (sink.layout) {
    Layout layout;
    layout.format = Layout::Format::Obj;
    sink.layout(layout);
  }
  std::string line;
  uint64_t line_no = 0, vertices = 0, texcoords = 0, normals = 0;
  std::vector<int64_t> poly;
  std::vector<uint32_t> ta, tb; // the polygon's corner keys
  std::vector<std::string> materials;
  uint32_t group = 0;
  while (read_line(in, line)) {
    ++line_no;
    const char* s = line.c_str();
    while (*s == ' ' || *s == '\t')
      ++s;
    const auto bad = [&](const char* what) { return "line " + std::to_string(line_no) + what; };
    if (s[0] == 'v' && (s[1] == ' ' || s[1] == '\t')) {
      double p[3];
      char* end = const_cast<char*>(s + 1);
      for (double& c : p) {
        char* start = end;
        c = std::strtod(start, &end);
        if (end == start) return bad(": bad vertex");
      }
      sink.vertex(p);
      if (sink.raw_vertex) sink.raw_vertex(line.data(), line.size());
      ++vertices;
    } else if (s[0] == 'f' && (s[1] == ' ' || s[1] == '\t')) {
      poly.clear(), ta.clear(), tb.clear();
      const char* c = s + 1;
      for (;;) {
        while (*c == ' ' || *c == '\t')
          ++c;
        if (!*c) break;
        int64_t v, t = -1, n = -1;
        if (!obj_index(c, vertices, v)) return bad(": bad face");
        if (*c == '/') {
          ++c;
          if (*c != '/' && !obj_index(c, texcoords, t)) return bad(": bad face");
          if (*c == '/' && (++c, !obj_index(c, normals, n))) return bad(": bad face");
        }
        if (*c && *c != ' ' && *c != '\t') return bad(": bad face");
        if (t < -1 || t >= int64_t(texcoords) || n < -1 || n >= int64_t(normals))
          return bad(": a face's vt or vn index is out of range");
        poly.push_back(v);
        ta.push_back(uint32_t(t + 1));
        tb.push_back(uint32_t(n + 1));
      }
      if (poly.size() < 3) return bad(": face with fewer than 3 corners");
      CornerKeys keys;
      keys.group = group;
      if (poly.size() > 3 && sink.polygon) sink.polygon(poly.size());
      for (size_t j = 2; j < poly.size(); ++j) {
        const int64_t t[3] = {poly[0], poly[j - 1], poly[j]};
        const size_t corner[3] = {0, j - 1, j};
        for (int k = 0; k < 3; ++k)
          keys.a[k] = ta[corner[k]], keys.b[k] = tb[corner[k]];
        sink.triangle(t, keys);
      }
    } else {
      if (s[0] == 'v' && s[1] == 't' && (s[2] == ' ' || s[2] == '\t')) ++texcoords;
      if (s[0] == 'v' && s[1] == 'n' && (s[2] == ' ' || s[2] == '\t')) ++normals;
      if (std::strncmp(s, "usemtl", 6) == 0 && (s[6] == ' ' || s[6] == '\t')) {
        std::string name = s + 7;
        name.erase(0, name.find_first_not_of(" \t"));
        name.erase(name.find_last_not_of(" \t") + 1);
        const auto it = std::find(materials.begin(), materials.end(), name);
        group = uint32_t(it - materials.begin()) + 1;
        if (it == materials.end()) {
          materials.push_back(name);
          if (sink.material) sink.material(group, name);
        }
      }
      if (sink.other_line) sink.other_line(line);
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
  if (!r.next_token(tok) || tok.find("OFF") == std::string::npos || tok.size() > 8 ||
      tok.find_first_not_of("STCNOF") != std::string::npos)
    return "not an ascii OFF file";
  Layout layout;
  layout.format = Layout::Format::Off;
  layout.off_keyword = tok;
  if (sink.layout) sink.layout(layout);
  double nv, nf, ne;
  if (!number(nv) || !number(nf) || !number(ne) || nv < 0 || nf < 0 || nv > 4e9 || nf > 4e9)
    return "bad OFF counts";
  std::vector<int64_t> poly;
  std::string raw;
  // The rest of the current line (colors, normals), trimmed.
  auto rest = [&] {
    std::string t = r.token_line.substr(r.token_pos);
    t.erase(0, t.find_first_not_of(" \t"));
    const size_t hash = t.find('#');
    if (hash != std::string::npos) t.erase(hash);
    t.erase(t.find_last_not_of(" \t") + 1);
    r.token_pos = r.token_line.size();
    return t;
  };
  for (double i = 0; i < nv; ++i) {
    double p[3];
    raw.clear();
    for (double& c : p) {
      if (!number(c)) return "truncated or malformed OFF vertex " + std::to_string(int64_t(i));
      raw.append(raw.empty() ? "" : " ").append(tok);
    }
    const std::string extra = rest();
    if (!extra.empty()) raw.append(" ").append(extra);
    sink.vertex(p);
    if (sink.raw_vertex) sink.raw_vertex(raw.data(), raw.size());
  }
  if (sink.vertices_only) return {};
  bool told = false;
  for (double i = 0; i < nf; ++i) {
    double k, v;
    if (!number(k) || k < 3 || k > 1e6)
      return "truncated or malformed OFF face " + std::to_string(int64_t(i));
    poly.clear();
    for (int j = 0; j < int(k); ++j) {
      if (!number(v) || !(std::fabs(v) < 9e18)) // 1e30 is no index (nor an int64)
        return "truncated or malformed OFF face " + std::to_string(int64_t(i));
      poly.push_back(int64_t(v));
    }
    if (!rest().empty() && !told && sink.uncarried) { // a face color
      told = true;
      sink.uncarried("OFF face colors");
    }
    if (poly.size() > 3 && sink.polygon) sink.polygon(poly.size());
    for (size_t j = 2; j < poly.size(); ++j) {
      const int64_t t[3] = {poly[0], poly[j - 1], poly[j]};
      sink.triangle(t, CornerKeys{});
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
