#include "fuzz_case.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "mesh_checks.h"

namespace vrs_test {

namespace {

class Bytes {
 public:
  Bytes(const uint8_t* d, size_t n) : d_(d), n_(n) {}
  size_t left() const { return n_ - i_; }
  uint8_t u8() { return i_ < n_ ? d_[i_++] : 0; }
  uint16_t u16() { return uint16_t(u8() | (u8() << 8)); }
  uint32_t u32() { return uint32_t(u16()) | (uint32_t(u16()) << 16); }
  float f32() {
    uint32_t b = u32();
    float f;
    std::memcpy(&f, &b, 4);
    return f;
  }

 private:
  const uint8_t* d_;
  size_t n_, i_ = 0;
};

void put16(std::vector<uint8_t>& b, uint16_t v) {
  b.push_back(uint8_t(v));
  b.push_back(uint8_t(v >> 8));
}
void put32(std::vector<uint8_t>& b, uint32_t v) {
  put16(b, uint16_t(v));
  put16(b, uint16_t(v >> 16));
}

} // namespace

FuzzCase decode_fuzz_case(const uint8_t* data, size_t size) {
  Bytes in(data, size);
  FuzzCase c;
  vrs::Options& o = c.options;
  const uint8_t f0 = in.u8(), f1 = in.u8();
  o.target.kind = vrs::TargetKind((f0 & 7) % 5);
  // Kinds 5-7 (0-2 again) cut the mesh into parts of 64 vertices: simplification by parts
  // on meshes the fuzzer makes (from 256 vertices), with lazy prices as parts need (the
  // other kinds are priced eagerly, as small meshes are by default).
  if ((f0 & 7) >= 5) {
    o.tuning.part_vertices = 64;
    o.tuning.lazy_from_faces = 0;
  }
  o.mode = vrs::Mode(((f0 >> 3) & 3) % 3);
  // Mode bits 3 (a second surface mode): split vertices welded freely instead of as seams.
  if (((f0 >> 3) & 3) == 3) o.split_vertices = vrs::SplitVertices::Weld;
  o.tuning.queue = f0 & 0x20 ? vrs::QueueKind::Heap : vrs::QueueKind::Intervals;
  o.tuning.mapping = f0 & 0x40 ? vrs::IntervalMapping::Logarithmic : vrs::IntervalMapping::Linear;
  o.simplify_boundary = f0 & 0x80;
  o.tuning.priority = f1 & 1 ? vrs::Priority::Factor : vrs::Priority::LocalError;
  const bool raw_indices = f1 & 2, locks = f1 & 4, cancel = f1 & 8, unchecked = f1 & 16;
  const bool constrained = f1 & 32, creases = f1 & 64;
  o.tuning.fill = f1 & 128 ? vrs::Fill::Projection : vrs::Fill::Best;

  const uint16_t intervals = in.u16();
  const uint8_t valence = in.u8();
  const uint32_t param = in.u32();
  const uint8_t cancel_after = in.u8(), lock_stride = in.u8();
  // Options: in range unless `unchecked` (then the core must refuse cleanly).
  o.tuning.intervals = unchecked ? int(int16_t(intervals)) : 2 + intervals % 2000;
  o.max_valence = unchecked ? int(int8_t(valence)) : 3 + valence % 62;
  float raw_param;
  std::memcpy(&raw_param, &param, 4);
  o.target.ratio = unchecked ? double(raw_param) : double(param) / 4294967295.0;
  o.target.max_factor = unchecked ? double(raw_param) : double(param % 100000) * 1e-5;
  if (cancel) c.cancel_after = 1 + cancel_after % 16;

  const size_t n = std::min<size_t>(in.u16(), in.left() / 12);
  c.mesh.positions.resize(3 * n);
  for (float& x : c.mesh.positions)
    x = in.f32();
  while (in.left() >= 6) {
    for (int k = 0; k < 3; ++k) {
      uint32_t i = in.u16();
      c.mesh.triangles.push_back(raw_indices ? i : uint32_t(i % (n + 1)));
    }
  }
  const size_t faces = c.mesh.face_count();
  o.target.faces = param % (faces + 2);
  o.target.vertices = param % (n + 2);
  if (constrained) { // every edge whose index sum falls on the stride: seams of any shape
    o.corner_sources = true;
    const uint32_t stride = 2 + lock_stride % 5;
    for (size_t i = 0; i < c.mesh.triangles.size(); ++i) {
      uint32_t a = c.mesh.triangles[i], b = c.mesh.triangles[i - i % 3 + (i + 1) % 3];
      if (a < n && b < n && (a + b) % stride == 0)
        c.constraints.insert(c.constraints.end(), {a, b});
    }
  }
  if (creases) o.feature_angle_deg = unchecked ? double(raw_param) : double(param % 180);
  // The cancel byte's high nibble: bit 3 asks for an error bound, bits 0-2 its size (a 500th of
  // the extent, doubled each step; 7: tracked only).
  if (cancel_after & 0x80) {
    const int step = (cancel_after >> 4) & 7;
    double extent = 0;
    for (float x : c.mesh.positions)
      if (std::isfinite(x)) extent = std::max(extent, double(std::fabs(x)));
    o.max_error = unchecked    ? double(raw_param)
                  : step == 7  ? std::numeric_limits<double>::infinity()
                  : extent > 0 ? extent * 0.002 * double(1 << step)
                               : 1.0;
  }
  if (locks) {
    c.locks.assign(n, 0);
    for (size_t v = 0; v < n; v += 1 + lock_stride % 7)
      c.locks[v] = 1;
  }
  return c;
}

std::vector<uint8_t> encode_fuzz_case(const vrs::Mesh& m, uint8_t flags0, uint8_t flags1,
                                      uint16_t intervals, uint32_t target_param) {
  std::vector<uint8_t> b{flags0, flags1};
  put16(b, intervals);
  b.push_back(29); // max valence 32
  put32(b, target_param);
  b.push_back(3); // cancel after 4 calls, when asked
  b.push_back(2); // lock every third vertex, when asked
  put16(b, uint16_t(m.vertex_count()));
  for (float x : m.positions) {
    uint32_t u;
    std::memcpy(&u, &x, 4);
    put32(b, u);
  }
  for (uint32_t i : m.triangles)
    put16(b, uint16_t(i));
  return b;
}

std::string run_fuzz_case(const uint8_t* data, size_t size) {
  FuzzCase c = decode_fuzz_case(data, size);
  if (!c.locks.empty()) c.options.locked = &c.locks;
  if (!c.constraints.empty()) c.options.constrained_edges = &c.constraints;
  bool progress_out_of_range = false;
  int calls = 0;
  if (c.cancel_after > 0)
    c.options.progress = [&](float f) {
      progress_out_of_range |= !(f >= 0 && f <= 1);
      return ++calls < c.cancel_after;
    };
  vrs::Mesh out = c.mesh;
  const vrs::Report rep = vrs::simplify(out, c.options);
  if (progress_out_of_range) return "progress reported outside [0, 1]";
  std::string e = check_run(c.mesh, out, c.options, rep);
  calls = 0; // the rerun cancels at the same call
  if (e.empty()) e = check_rerun(c.mesh, c.options, out, rep);
  return e;
}

} // namespace vrs_test
