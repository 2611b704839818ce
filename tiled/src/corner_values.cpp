#include "corner_values.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "mesh_stream.h"

namespace vrs::tiled {

CornerValues::CornerValues(const std::string& path, int floats) : floats_(floats) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) return; // no such lines in the input
  struct stat st;
  if (::fstat(fd, &st) == 0 && st.st_size >= 4 * floats) {
    void* p = ::mmap(nullptr, size_t(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
    if (p == MAP_FAILED) {
      ::close(fd);
      throw std::runtime_error("cannot map " + path);
    }
    data_ = static_cast<const float*>(p);
    bytes_ = size_t(st.st_size);
    lines_ = bytes_ / (4 * size_t(floats));
  }
  ::close(fd);
}

CornerValues::~CornerValues() {
  if (data_) ::munmap(const_cast<float*>(data_), bytes_);
}

namespace {

bool same_bits(const float* x, const float* y, int floats) {
  static const float zero[3] = {0, 0, 0}; // a corner without a line: zero, as vcg reads it
  return std::memcmp(x ? x : zero, y ? y : zero, 4 * size_t(floats)) == 0;
}

} // namespace

bool same_texcoord(const CornerValues* vt, uint32_t a, uint32_t b) {
  return a == b || (vt && !vt->empty() && same_bits(vt->at(a), vt->at(b), 2));
}

bool same_normal(const CornerValues* vn, uint32_t a, uint32_t b, double crease_cos) {
  if (a == b) return true;
  if (!vn || vn->empty()) return false;
  const float *x = vn->at(a), *y = vn->at(b);
  if (same_bits(x, y, 3)) return true;
  if (!x || !y) return false;
  double dot = 0, xx = 0, yy = 0;
  for (int i = 0; i < 3; ++i)
    dot += double(x[i]) * y[i], xx += double(x[i]) * x[i], yy += double(y[i]) * y[i];
  return xx > 0 && yy > 0 && dot / std::sqrt(xx * yy) >= crease_cos;
}

bool flat_by_value(const std::string& keys_path, uint64_t faces, const CornerValues& vn) {
  std::FILE* f = std::fopen(keys_path.c_str(), "rb");
  if (!f) throw std::runtime_error("cannot read " + keys_path);
  std::setvbuf(f, nullptr, _IOFBF, 1 << 20);
  bool flat = true;
  CornerKeys k;
  for (uint64_t i = 0; i < faces && flat; ++i) {
    if (std::fread(&k, sizeof k, 1, f) != 1) {
      std::fclose(f);
      throw std::runtime_error("cannot read " + keys_path + " whole");
    }
    flat = same_bits(vn.at(k.b[0]), vn.at(k.b[1]), 3) && same_bits(vn.at(k.b[0]), vn.at(k.b[2]), 3);
  }
  std::fclose(f);
  return flat;
}

} // namespace vrs::tiled
