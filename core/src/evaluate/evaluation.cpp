#include "evaluate/evaluation.h"

#include <algorithm>
#include <array>
#include <limits>

namespace vrs {

double distance_to_line(Vec3 p, Vec3 a, Vec3 b) {
  Vec3 d = b - a;
  double l2 = dot(d, d);
  if (!(l2 > 0)) return length(p - a);
  return length(cross(p - a, d)) / std::sqrt(l2);
}

void vertex_cone(const float* pos, const uint32_t* tris, const Topology& topo, uint32_t v,
                 float* cone, float* fan_area) {
  // Each face adds its unit normal. Area weights in float underflow to nothing for the small
  // faces of a mesh that also holds one huge coordinate (found by the fuzzer: a face flipped
  // against a vertex whose normal had vanished). The faces in the order topology lists them
  // (the input's): the same float sums on any number of threads.
  auto at = [&](uint32_t u) { return Vec3{pos[3 * u], pos[3 * u + 1], pos[3 * u + 2]}; };
  auto face_cross = [&](uint32_t f) {
    const Vec3 a = at(tris[3 * size_t(f)]);
    return cross(at(tris[3 * size_t(f) + 1]) - a, at(tris[3 * size_t(f) + 2]) - a);
  };
  constexpr uint32_t kKept = 32; // the first faces' normals, kept for the second loop
  std::array<Vec3, kKept> kept;
  const uint32_t* faces = topo.faces_of(v);
  const uint32_t count = topo.valence(v);
  float s[3] = {0, 0, 0};
  float area = 0;
  for (uint32_t i = 0; i < count; ++i) {
    const Vec3 c = face_cross(faces[i]);
    const Vec3 u = normalized(c);
    if (i < kKept) kept[i] = u;
    s[0] += float(u.x), s[1] += float(u.y), s[2] += float(u.z);
    area += float(0.5 * length(c));
  }
  if (fan_area) *fan_area = area;
  // Faces that cancel out (a fin, a sheet folded onto itself) leave a rounding residue whose
  // direction means nothing: no normal there (found by the fuzzer).
  const Vec3 sum{s[0], s[1], s[2]};
  const Vec3 u = length(sum) > kMinNormalSum ? normalized(sum) : Vec3{};
  cone[0] = float(u.x), cone[1] = float(u.y), cone[2] = float(u.z);
  const Vec3 axis{cone[0], cone[1], cone[2]};
  float least = 1.0f; // least cosine between the normal and a face
  for (uint32_t i = 0; i < count; ++i)
    least =
        std::min(least, float(dot(i < kKept ? kept[i] : normalized(face_cross(faces[i])), axis)));
  // The sine of the cone's half-angle, 1 past 90 degrees.
  cone[3] = least > 0 ? std::sqrt(std::max(0.0f, 1 - least * least)) : 1.0f;
}

std::vector<float> vertex_normals(const std::vector<float>& pos,
                                  const std::vector<uint32_t>& tris) {
  const size_t count = pos.size() / 3;
  Topology topo;
  topo.build(tris, count);
  std::vector<float> n(4 * count);
  for (size_t v = 0; v < count; ++v)
    vertex_cone(pos.data(), tris.data(), topo, uint32_t(v), &n[4 * v], nullptr);
  return n;
}

Vec3 mesh_plane_normal(const float* pos, const std::vector<uint32_t>& tris) {
  Vec3 sum;
  for (size_t i = 0; i + 2 < tris.size(); i += 3) {
    auto at = [&](uint32_t v) { return Vec3{pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]}; };
    Vec3 a = at(tris[i]), b = at(tris[i + 1]), c = at(tris[i + 2]);
    Vec3 n = cross(b - a, c - a);
    if (is_finite(n)) sum = sum + n;
  }
  Vec3 n = normalized(sum);
  return length(n) > 0 ? n : Vec3{0, 0, 1};
}

Vec3 Evaluator::average_plane_normal(const Vec3* p, int k, Vec3 fan) const {
  Vec3 sum;
  // Each triple's normal is turned to agree with the fan's normal before averaging; otherwise
  // triples taken in different orders cancel each other.
  auto add = [&](int i, int j, int l) {
    Vec3 n = normalized(cross(p[j] - p[i], p[l] - p[i]));
    sum = dot(n, fan) < 0 ? sum - n : sum + n;
  };
  if (k <= all_triples_) {
    for (int i = 0; i < k; ++i)
      for (int j = i + 1; j < k; ++j)
        for (int l = j + 1; l < k; ++l)
          add(i, j, l);
  } else {
    for (int i = 0; i < k; ++i) {
      add(i, (i + k / 3) % k, (i + 2 * k / 3) % k);
      add(i, (i + 1) % k, (i + k / 2) % k);
    }
  }
  return normalized(sum);
}

Evaluation Evaluator::evaluate(uint32_t v, const Ring& ring, bool boundary_line) const {
  Evaluation e;
  e.factor = std::numeric_limits<double>::infinity();
  const int k = ring.verts;
  if (k < 2) return e;
  Vec3 c = position(v);
  UnsetArray<Vec3, kMaxRing + 1> p;
  for (int i = 0; i < k; ++i)
    p[i] = position(ring.v[i]);

  if (k == 2) { // a corner: the paper's two-neighbour factor
    e.factor = distance_to_line(c, p[0], p[1]);
    e.normal = normalized(cross(p[0] - c, p[1] - c));
    return e;
  }

  // Area-weighted fan normal: orients the plane so that "counter-clockwise" means the same as
  // the triangles' own orientation.
  Vec3 fan;
  for (int i = 0; i < ring.faces; ++i)
    fan = fan + cross(p[i] - c, p[wrap(i + 1, k)] - c);

  e.fan_normal = normalized(fan);
  Vec3 n;
  switch (mode_) {
  case Mode::Surface3D:
    n = average_plane_normal(p.data(), k, fan);
    if (!(length(n) > 0)) n = normalized(fan); // all neighbours collinear
    break;
  case Mode::Terrain25D: n = Vec3{0, 0, fan.z < 0 ? -1.0 : 1.0}; break;
  case Mode::Planar2D: n = dot(fan, plane_) < 0 ? plane_ * -1.0 : plane_; break;
  }
  if (!(length(n) > 0) || !(dot(n, fan) > 0)) return e; // no plane to project on: keep

  double sum = 0;
  for (int i = 0; i < k; ++i)
    sum += std::fabs(dot(c - p[i], n));
  e.factor = sum / k;
  if (boundary_line && !ring.closed()) {
    // Corners of the outline stay: removing one cuts a piece off the mesh's shape, which a
    // factor (a distance) cannot price. A turn above 30° is a corner, as a polyline would say.
    // (The local error can price it: with it, the Simplifier sets no corner.)
    Vec3 in = normalized(c - p[k - 1]), out = normalized(p[0] - c);
    if (!(dot(in, out) >= corner_cos_)) {
      e.factor = std::numeric_limits<double>::infinity();
      return e;
    }
    e.factor = std::max(e.factor, distance_to_line(c, p[0], p[k - 1]));
  }
  if (!std::isfinite(e.factor)) e.factor = std::numeric_limits<double>::infinity();
  e.normal = n;
  return e;
}

} // namespace vrs
