#include "exact_vertices.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>

#include "mesh_stream.h"
#include "output_file.h"

namespace vrs_tool {

namespace {

enum Type { I8, U8, I16, U16, I32, U32, F32, F64, Bad };

Type type_of(const std::string& line, std::string* name = nullptr) {
  char t[32] = {0}, n[64] = {0};
  if (std::sscanf(line.c_str(), "property %31s %63s", t, n) != 2) return Bad;
  if (name) *name = n;
  const std::string s = t;
  if (s == "char" || s == "int8") return I8;
  if (s == "uchar" || s == "uint8") return U8;
  if (s == "short" || s == "int16") return I16;
  if (s == "ushort" || s == "uint16") return U16;
  if (s == "int" || s == "int32") return I32;
  if (s == "uint" || s == "uint32") return U32;
  if (s == "float" || s == "float32") return F32;
  if (s == "double" || s == "float64") return F64;
  return Bad; // a list, or unknown
}

size_t size_of(int t) {
  static const size_t sizes[] = {1, 1, 2, 2, 4, 4, 4, 8, 0};
  return sizes[t];
}

// One value of type t from text, as its little-endian bytes.
void parse(int t, const char* text, unsigned char* out) {
  switch (t) {
  case F32: {
    const float v = std::strtof(text, nullptr);
    std::memcpy(out, &v, 4);
    break;
  }
  case F64: {
    const double v = std::strtod(text, nullptr);
    std::memcpy(out, &v, 8);
    break;
  }
  default: {
    const long long v = std::strtoll(text, nullptr, 10);
    const int8_t a = int8_t(v);
    const int16_t b = int16_t(v);
    const int32_t c = int32_t(v);
    if (size_of(t) == 1) std::memcpy(out, &a, 1);
    if (size_of(t) == 2) std::memcpy(out, &b, 2);
    if (size_of(t) == 4) std::memcpy(out, &c, 4);
  }
  }
}

// The shortest text that reads back as the same float or double (at most 9 or 17 significant
// digits): 0.1809f is "0.1809", not "0.180899993".
template <class T> std::string shortest(T v) {
  char b[64];
  const auto r = std::to_chars(b, b + sizeof b, v, std::chars_format::general);
  return std::string(b, r.ptr);
}

// One value of type t (little-endian bytes) as text with round-trip digits.
std::string text_of(int t, const unsigned char* p) {
  char b[40];
  switch (t) {
  case F32: {
    float v;
    std::memcpy(&v, p, 4);
    return shortest(v);
  }
  case F64: {
    double v;
    std::memcpy(&v, p, 8);
    return shortest(v);
  }
  case I8: std::snprintf(b, sizeof b, "%d", int(int8_t(p[0]))); break;
  case U8: std::snprintf(b, sizeof b, "%u", unsigned(p[0])); break;
  case I16: {
    int16_t v;
    std::memcpy(&v, p, 2);
    std::snprintf(b, sizeof b, "%d", int(v));
    break;
  }
  case U16: {
    uint16_t v;
    std::memcpy(&v, p, 2);
    std::snprintf(b, sizeof b, "%u", unsigned(v));
    break;
  }
  case I32: {
    int32_t v;
    std::memcpy(&v, p, 4);
    std::snprintf(b, sizeof b, "%d", v);
    break;
  }
  default: {
    uint32_t v;
    std::memcpy(&v, p, 4);
    std::snprintf(b, sizeof b, "%u", v);
    break;
  }
  }
  return b;
}

// Whether a coordinate written as `token` holds more than a float: its float, printed with as
// many significant digits as the token has, reads back as another number. (Most decimals are
// no float, nor double, exactly: "0.1809" fits a float as well as the text says.)
// A number as a text file writes it, judged by its value as the core judges every double.
bool beyond_float(const std::string& token) {
  return vrs::beyond_float(std::strtod(token.c_str(), nullptr));
}

} // namespace

ExactVertices::ExactVertices(const std::string& input, const std::string& output, bool ascii_output)
    : in_format_(vrs::tiled::format_of(input)), out_format_(vrs::tiled::format_of(output)) {
  if (in_format_ != "ply" && in_format_ != "obj" && in_format_ != "off") return;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(input.c_str(), "rb"), &std::fclose);
  if (!in) return;
  // A PLY's header first: its vertex properties decide whether anything is needed at all.
  bool doubles = false, lists = false;
  std::vector<bool> double_xyz(3, false);
  if (in_format_ == "ply") {
    vrs::tiled::StreamSink probe;
    probe.layout = [&](const vrs::tiled::Layout& l) {
      props_ = l.vertex_properties;
      ascii_in_ = l.ply_format.find("ascii") != std::string::npos;
      big_in_ = l.ply_format.find("big") != std::string::npos;
      for (const std::string& p : props_) {
        std::string name;
        const Type t = type_of(p, &name);
        types_.push_back(t);
        lists = lists || t == Bad;
        doubles = doubles || t == F64;
        if (t == F64 && name.size() == 1 && name[0] >= 'x' && name[0] <= 'z')
          double_xyz[size_t(name[0] - 'x')] = true;
      }
      throw 0; // the header is all this pass wants
    };
    try {
      vrs::tiled::read_mesh_stream(in.get(), input, probe);
    } catch (int) {
    }
    std::rewind(in.get());
  }
  const bool ply_records =
      in_format_ == "ply" && out_format_ == "ply" && !lists && (doubles || ascii_output);
  const bool text_out = out_format_ == "obj" || out_format_ == "off";
  const bool float_ply = in_format_ == "ply" && !double_xyz[0] && !double_xyz[1] && !double_xyz[2];
  // Nothing to lose: a float PLY written as binary PLY, or as STL (float anyway).
  if (!ply_records && !text_out && float_ply) return;

  vrs::tiled::StreamSink sink;
  sink.vertices_only = true;
  double last[3] = {0, 0, 0};
  // A binary PLY's doubles are judged by value, text by its digits (see beyond_float).
  const bool binary_values = in_format_ == "ply" && !ascii_in_;
  std::vector<int> xyz_token(3, -1); // an ascii PLY's x, y, z: which value of the line
  for (size_t i = 0; i < props_.size(); ++i) {
    std::string name;
    type_of(props_[i], &name);
    if (name.size() == 1 && name[0] >= 'x' && name[0] <= 'z')
      xyz_token[size_t(name[0] - 'x')] = int(i);
  }
  if (in_format_ != "ply") xyz_token = {0, 1, 2};
  sink.vertex = [&](const double p[3]) {
    for (int a = 0; a < 3; ++a) {
      last[a] = p[a];
      if (binary_values) beyond_float_ = beyond_float_ || vrs::beyond_float(p[a]);
    }
    xyz_.insert(xyz_.end(), p, p + 3);
  };
  sink.triangle = [](const int64_t*, const vrs::tiled::CornerKeys&) {};
  sink.raw_vertex = [&](const char* data, size_t size) {
    if (!binary_values && !beyond_float_) { // the coordinates' own tokens
      std::vector<std::string> tokens;
      const char* c = data;
      const char* end = data + size;
      if (in_format_ == "obj")
        c = std::find_if(c, end, [](char ch) { return ch == ' ' || ch == '\t'; });
      while (c < end) {
        while (c < end && (*c == ' ' || *c == '\t'))
          ++c;
        const char* e = c;
        while (e < end && *e != ' ' && *e != '\t')
          ++e;
        if (e > c) tokens.emplace_back(c, e);
        c = e;
      }
      for (int a = 0; a < 3; ++a)
        if (xyz_token[size_t(a)] >= 0 && size_t(xyz_token[size_t(a)]) < tokens.size())
          beyond_float_ = beyond_float_ || beyond_float(tokens[size_t(xyz_token[size_t(a)])]);
    }
    if (ply_records) {
      if (ascii_in_) offsets_.push_back(records_.size());
      records_.append(data, size);
    }
    if (!text_out) return;
    coord_offsets_.push_back(coords_.size());
    if (in_format_ == "obj" && out_format_ == "obj") { // the whole v line, as written
      coords_.append(data, size);
      return;
    }
    if (in_format_ == "ply" && !ascii_in_) { // round-trip digits of each coordinate's type
      for (int a = 0; a < 3; ++a)
        coords_ +=
            (a ? " " : "") + (double_xyz[size_t(a)] ? shortest(last[a]) : shortest(float(last[a])));
      return;
    }
    // Text: the coordinates' own tokens (an OBJ's after "v"; an ascii PLY's x, y, z are its
    // first three values in the usual layout, else with round-trip digits).
    std::string text(data, size);
    size_t at = text.find_first_not_of(" \t");
    if (in_format_ == "obj") at = text.find_first_not_of(" \t", at + 1);
    std::string got;
    for (int k = 0; k < 3 && at != std::string::npos; ++k) {
      const size_t end = text.find_first_of(" \t", at);
      got += (k ? " " : "") + text.substr(at, end == std::string::npos ? end : end - at);
      at = end == std::string::npos ? end : text.find_first_not_of(" \t", end);
    }
    const bool xyz_first =
        in_format_ != "ply" ||
        (props_.size() >= 3 && props_[0].find(" x") != std::string::npos &&
         props_[1].find(" y") != std::string::npos && props_[2].find(" z") != std::string::npos);
    if (!xyz_first) got = shortest(last[0]) + " " + shortest(last[1]) + " " + shortest(last[2]);
    coords_ += got;
  };
  if (!vrs::tiled::read_mesh_stream(in.get(), input, sink).empty()) {
    records_ = {}, xyz_ = {}, offsets_ = {}, coords_ = {}, coord_offsets_ = {};
    beyond_float_ = false;
    return;
  }
  if (ascii_in_ && ply_records) offsets_.push_back(records_.size());
  coord_offsets_.push_back(coords_.size());
  // What a text output needs: OFF always (vcglib prints 7 digits), OBJ when a coordinate has
  // more than a float (our writer prints a float's 9).
  const bool text_needed = out_format_ == "off" || (out_format_ == "obj" && beyond_float_) ||
                           (out_format_ == "obj" && in_format_ == "ply" && !float_ply);
  needed_ = ply_records || (text_out && text_needed);
  if (!needed_) coords_ = {}, coord_offsets_ = {}, records_ = {}, offsets_ = {};
  if (!beyond_float_) xyz_ = {};
}

bool ExactVertices::core_positions(size_t vertices, std::vector<float>& out) const {
  if (!beyond_float_ || xyz_.size() != 3 * vertices) return false;
  out = vrs::float_positions(xyz_.data(), vertices);
  return true;
}

std::string ExactVertices::rewrite_text(const std::string& written, const std::string& output,
                                        const std::vector<uint32_t>& kept) const {
  std::ifstream in(written, std::ios::binary);
  if (!in) return "cannot read back " + written;
  std::ofstream out(output, std::ios::binary | std::ios::trunc);
  if (!out) return std::strerror(errno);
  std::string line;
  size_t k = 0, line_no = 0, first_vertex_line = 2; // OFF: keyword, counts, then the vertices
  const bool obj = out_format_ == "obj";
  while (std::getline(in, line)) {
    const bool vertex = obj ? line.rfind("v ", 0) == 0
                            : line_no++ >= first_vertex_line && k < kept.size() && !line.empty();
    if (!obj && line_no == 1 && line.find_first_of("0123456789") != std::string::npos)
      first_vertex_line = 1; // counts on the keyword's line
    if (!vertex || k >= kept.size()) {
      out << line << '\n';
      continue;
    }
    const uint32_t v = kept[k++];
    const std::string coords =
        coords_.substr(coord_offsets_[v], coord_offsets_[v + 1] - coord_offsets_[v]);
    if (obj && in_format_ == "obj") { // the input's own line
      out << coords << '\n';
      continue;
    }
    // The written line's first three values (after "v") give way to the input's.
    size_t at = obj ? 1 : 0;
    for (int t = 0; t < 3 && at != std::string::npos; ++t) {
      at = line.find_first_not_of(" \t", at);
      if (at != std::string::npos) at = line.find_first_of(" \t", at);
    }
    out << (obj ? "v " : "") << coords << (at == std::string::npos ? "" : line.substr(at)) << '\n';
  }
  if (k != kept.size()) return "the written vertex count differs from the kept one";
  out.flush();
  return out ? "" : std::strerror(errno);
}

std::string ExactVertices::rewrite(const std::string& written, const std::string& output,
                                   const std::vector<uint32_t>& kept) const {
  if (out_format_ != "ply") return rewrite_text(written, output, kept);
  std::ifstream in(written, std::ios::binary);
  if (!in) return "cannot read back " + written;
  std::string line, header;
  bool ascii_out = false, in_vertex = false;
  uint64_t vertex_count = 0;
  size_t written_record = 0; // bytes of one vertex as vcglib wrote it (binary)
  while (std::getline(in, line)) {
    if (line.rfind("format ascii", 0) == 0) ascii_out = true;
    if (line.rfind("element ", 0) == 0) {
      in_vertex = line.rfind("element vertex ", 0) == 0;
      if (in_vertex) vertex_count = std::strtoull(line.c_str() + 15, nullptr, 10);
      if (in_vertex) {
        header += line + "\n";
        for (const std::string& p : props_)
          header += p + "\n";
        continue;
      }
    }
    if (in_vertex && line.rfind("property ", 0) == 0) {
      const Type t = type_of(line);
      if (t == Bad) return "unexpected vertex property in " + written + ": " + line;
      written_record += size_of(t);
      continue;
    }
    header += line + "\n";
    if (line == "end_header") break;
  }
  if (vertex_count != kept.size()) return "the written vertex count differs from the kept one";
  // Past the vertices vcglib wrote.
  if (ascii_out) {
    for (uint64_t v = 0; v < vertex_count; ++v)
      std::getline(in, line);
  } else {
    in.seekg(std::streamoff(written_record * vertex_count), std::ios::cur);
  }
  if (!in) return "cannot read back " + written;
  std::ofstream out(output, std::ios::binary | std::ios::trunc);
  if (!out) return std::strerror(errno);
  out << header;
  size_t input_record = 0;
  for (int t : types_)
    input_record += size_of(t);
  std::vector<unsigned char> value(8);
  std::string record;
  for (uint32_t v : kept) {
    record.clear();
    if (ascii_in_) {
      const std::string text = records_.substr(offsets_[v], offsets_[v + 1] - offsets_[v]);
      if (ascii_out) {
        record = text + "\n"; // as the input wrote it
      } else {
        size_t at = 0;
        for (int t : types_) {
          const size_t end = std::min(text.find(' ', at), text.size());
          parse(t, text.substr(at, end - at).c_str(), value.data());
          record.append(reinterpret_cast<const char*>(value.data()), size_of(t));
          at = end + 1;
        }
      }
    } else {
      const unsigned char* p =
          reinterpret_cast<const unsigned char*>(records_.data()) + size_t(v) * input_record;
      for (int t : types_) {
        const size_t n = size_of(t);
        for (size_t i = 0; i < n; ++i)
          value[i] = big_in_ ? p[n - 1 - i] : p[i]; // little endian, as vcglib writes
        if (ascii_out)
          record += (record.empty() ? "" : " ") + text_of(t, value.data());
        else
          record.append(reinterpret_cast<const char*>(value.data()), n);
        p += n;
      }
      if (ascii_out) record += "\n";
    }
    out.write(record.data(), std::streamsize(record.size()));
  }
  if (in.peek() != std::char_traits<char>::eof()) out << in.rdbuf(); // the faces, as written
  out.flush();
  return out ? "" : std::strerror(errno);
}

} // namespace vrs_tool
