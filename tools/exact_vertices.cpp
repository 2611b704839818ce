#include "exact_vertices.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>

#include "mesh_stream.h"

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

// One value of type t (little-endian bytes) as text with round-trip digits.
std::string text_of(int t, const unsigned char* p) {
  char b[40];
  switch (t) {
  case F32: {
    float v;
    std::memcpy(&v, p, 4);
    std::snprintf(b, sizeof b, "%.9g", double(v));
    break;
  }
  case F64: {
    double v;
    std::memcpy(&v, p, 8);
    std::snprintf(b, sizeof b, "%.17g", v);
    break;
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

} // namespace

ExactVertices::ExactVertices(const std::string& ply, bool ascii_output) {
  const size_t dot = ply.rfind('.');
  std::string ext = dot == std::string::npos ? "" : ply.substr(dot);
  for (char& c : ext)
    c = char(std::tolower((unsigned char)c));
  if (ext != ".ply") return;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(ply.c_str(), "rb"), &std::fclose);
  if (!in) return;
  // The header first: whether anything is needed at all.
  vrs::tiled::StreamSink probe;
  bool doubles = false, lists = false;
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
      if (t == F64 && (name == "x" || name == "y" || name == "z")) double_positions_ = true;
    }
    throw 0; // the header is all this pass wants
  };
  try {
    vrs::tiled::read_mesh_stream(in.get(), ply, probe);
  } catch (int) {
  }
  if (lists || !(doubles || ascii_output)) {
    double_positions_ = false;
    return;
  }
  std::rewind(in.get());
  vrs::tiled::StreamSink sink;
  sink.vertices_only = true;
  sink.vertex = [&](const double p[3]) {
    if (double_positions_) xyz_.insert(xyz_.end(), p, p + 3);
  };
  sink.triangle = [](const int64_t*, const vrs::tiled::CornerKeys&) {};
  sink.raw_vertex = [&](const char* data, size_t size) {
    if (ascii_in_) offsets_.push_back(records_.size());
    records_.append(data, size);
  };
  if (!vrs::tiled::read_mesh_stream(in.get(), ply, sink).empty()) {
    records_ = {}, xyz_ = {}, offsets_ = {};
    double_positions_ = false;
    return;
  }
  if (ascii_in_) offsets_.push_back(records_.size());
  needed_ = true;
}

bool ExactVertices::core_positions(size_t vertices, std::vector<float>& out) const {
  if (!double_positions_ || xyz_.size() != 3 * vertices) return false;
  out.resize(xyz_.size());
  for (size_t i = 0; i < xyz_.size(); ++i)
    out[i] = float(xyz_[i] - xyz_[i % 3]);
  return true;
}

std::string ExactVertices::rewrite(const std::string& written, const std::string& output,
                                   const std::vector<uint32_t>& kept) const {
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
