// Small double-precision vector helpers. Geometry runs in double so that float inputs up to
// FLT_MAX can be squared and crossed without overflow.
#pragma once

#include <cmath>
#include <cstddef>

namespace vrs {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3 operator-(Vec3 a, Vec3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3 operator*(Vec3 a, double s) {
  return {a.x * s, a.y * s, a.z * s};
}
inline double dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(Vec3 a) {
  return std::sqrt(dot(a, a));
}
inline double triangle_area(Vec3 a, Vec3 b, Vec3 c) {
  return 0.5 * length(cross(b - a, c - a));
}
inline bool is_finite(Vec3 a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

// Unit vector, or the zero vector when `a` is too short to have a direction.
inline Vec3 normalized(Vec3 a) {
  double l = length(a);
  return l > 0 && std::isfinite(l) ? a * (1.0 / l) : Vec3{};
}

struct Vec2 {
  double x = 0, y = 0;
};

// A fixed array of vectors that starts unset (a Vec3 or Vec2 alone zeroes itself): the ring
// buffers hold kMaxRing + 1 entries and a plan writes a handful, and zeroing them all took a
// noticeable share of a run. Read only what was written.
template <class T, size_t N> class UnsetArray {
 public:
  UnsetArray() {} // the union's member is left unconstructed
  T& operator[](size_t i) { return v_[i]; }
  const T& operator[](size_t i) const { return v_[i]; }
  T* data() { return v_; }
  const T* data() const { return v_; }

 private:
  union {
    T v_[N];
  };
};

// Twice the signed area of (a, b, c): > 0 when counter-clockwise.
inline double orient2d(Vec2 a, Vec2 b, Vec2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Orthonormal basis (u, v) of the plane with unit normal n, right-handed: u x v = n.
inline void plane_basis(Vec3 n, Vec3& u, Vec3& v) {
  Vec3 a = std::fabs(n.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  u = normalized(cross(a, n));
  v = cross(n, u);
}

// Triangle shape quality in [0, 1]: 1 for equilateral, 0 for no area (4√3·area / Σ edge²).
inline double triangle_quality(Vec3 a, Vec3 b, Vec3 c) {
  double area2 = length(cross(b - a, c - a));
  double sum = dot(b - a, b - a) + dot(c - b, c - b) + dot(a - c, a - c);
  return sum > 0 ? 3.4641016151377544 * area2 / sum : 0.0; // 2√3 = 4√3 / 2
}

// Calls visit(x) at the centroid of each of the triangle (a, b, c)'s L x L sub-triangles, in
// order (each row's upward one, then the downward one beside it), until it answers true (then
// true): the sample points every fold-over and distance measure on a new triangle uses.
template <class Visit> bool each_grid_point(Vec3 a, Vec3 b, Vec3 c, int L, Visit&& visit) {
  for (int i = 0; i < L; ++i)
    for (int j = 0; i + j < L; ++j) {
      const int k = L - 1 - i - j; // the sub-triangle pointing up at (i, j, k)
      if (visit((a * (i + 1.0 / 3) + b * (j + 1.0 / 3) + c * (k + 1.0 / 3)) * (1.0 / L)))
        return true;
      if (k >= 1 &&
          visit((a * (i + 2.0 / 3) + b * (j + 2.0 / 3) + c * (k - 1 + 2.0 / 3)) * (1.0 / L)))
        return true;
    }
  return false;
}

} // namespace vrs
