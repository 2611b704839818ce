#include "evaluation.h"

#include <algorithm>
#include <limits>

namespace vrs {

double distance_to_line(Vec3 p, Vec3 a, Vec3 b) {
  Vec3 d = b - a;
  double l2 = dot(d, d);
  if (!(l2 > 0)) return length(p - a);
  return length(cross(p - a, d)) / std::sqrt(l2);
}

std::vector<float> vertex_normals(const std::vector<float>& pos,
                                  const std::vector<uint32_t>& tris) {
  // Each face adds its unit normal. Area weights in float underflow to nothing for the small
  // faces of a mesh that also holds one huge coordinate (found by the fuzzer: a face flipped
  // against a vertex whose normal had vanished).
  auto at = [&](uint32_t v) { return Vec3{pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]}; };
  const size_t count = pos.size() / 3;
  std::vector<float> n(4 * count, 0.0f);
  auto face_normal = [&](size_t i) {
    const Vec3 a = at(tris[i]);
    return normalized(cross(at(tris[i + 1]) - a, at(tris[i + 2]) - a));
  };
  for (size_t i = 0; i + 2 < tris.size(); i += 3) {
    const Vec3 u = face_normal(i);
    for (int k = 0; k < 3; ++k) {
      float* s = &n[4 * size_t(tris[i + k])];
      s[0] += float(u.x), s[1] += float(u.y), s[2] += float(u.z);
    }
  }
  std::vector<float> least(count, 1.0f); // per vertex: least cosine between normal and a face
  for (size_t v = 0; v < count; ++v) {
    // Faces that cancel out (a fin, a sheet folded onto itself) leave a rounding residue whose
    // direction means nothing: no normal there (found by the fuzzer).
    float* s = &n[4 * v];
    Vec3 sum{s[0], s[1], s[2]};
    Vec3 u = length(sum) > kMinNormalSum ? normalized(sum) : Vec3{};
    s[0] = float(u.x), s[1] = float(u.y), s[2] = float(u.z);
  }
  for (size_t i = 0; i + 2 < tris.size(); i += 3) {
    const Vec3 u = face_normal(i);
    for (int k = 0; k < 3; ++k) {
      const float* s = &n[4 * size_t(tris[i + k])];
      float& l = least[tris[i + k]];
      l = std::min(l, float(dot(u, Vec3{s[0], s[1], s[2]})));
    }
  }
  for (size_t v = 0; v < count; ++v) // the sine of the cone's half-angle, 1 past 90 degrees
    n[4 * v + 3] = least[v] > 0 ? std::sqrt(std::max(0.0f, 1 - least[v] * least[v])) : 1.0f;
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
    fan = fan + cross(p[i] - c, p[(i + 1) % k] - c);

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
