#include "test_meshes.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#ifndef VRS_CGAL_DATA
#define VRS_CGAL_DATA ""
#endif

namespace vrs_test {

namespace {

bool next_line(std::istream& in, std::string& line) {
  while (std::getline(in, line)) {
    size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    if (line.find_first_not_of(" \t\r") != std::string::npos) return true;
  }
  return false;
}

} // namespace

vrs::Mesh read_off(const std::string& path) {
  vrs::Mesh m;
  std::ifstream in(path);
  std::string line;
  if (!next_line(in, line) || line.find("OFF") == std::string::npos) return {};
  std::istringstream header(line.substr(line.find("OFF") + 3));
  size_t nv = 0, nf = 0;
  if (!(header >> nv >> nf)) {
    if (!next_line(in, line)) return {};
    std::istringstream counts(line);
    if (!(counts >> nv >> nf)) return {};
  }
  for (size_t i = 0; i < nv; ++i) {
    if (!next_line(in, line)) return {};
    std::istringstream s(line);
    float x, y, z;
    if (!(s >> x >> y >> z)) return {};
    m.positions.insert(m.positions.end(), {x, y, z});
  }
  for (size_t i = 0; i < nf; ++i) {
    if (!next_line(in, line)) return {};
    std::istringstream s(line);
    size_t n;
    s >> n;
    std::vector<uint32_t> poly(n);
    for (auto& p : poly)
      s >> p;
    if (!s) return {};
    for (size_t j = 1; j + 1 < n; ++j)
      m.triangles.insert(m.triangles.end(), {poly[0], poly[j], poly[j + 1]});
  }
  return m;
}

std::string cgal_mesh(const std::string& name) {
  std::string path = std::string(VRS_CGAL_DATA) + "/" + name;
  std::ifstream f(path);
  return f ? path : std::string();
}

vrs::Mesh hexagon_fan(float h) {
  vrs::Mesh m;
  for (int i = 0; i < 6; ++i) {
    float a = float(i) * 3.14159265f / 3.0f;
    m.positions.insert(m.positions.end(), {std::cos(a), std::sin(a), 0.0f});
  }
  m.positions.insert(m.positions.end(), {0.0f, 0.0f, h});
  for (uint32_t i = 0; i < 6; ++i)
    m.triangles.insert(m.triangles.end(), {6u, i, (i + 1) % 6});
  return m;
}

vrs::Mesh concave_fan() {
  // Ring (counter-clockwise): an arrow whose notch at vertex 3 makes it concave, star-shaped
  // from the centre (index 6) placed near the notch.
  vrs::Mesh m;
  m.positions = {2, 0, 0, 2, 2, 0, 0, 3, 0, -0.3f, 1.2f, 0, -2, 2, 0, -2, 0, 0, 0, 0.5f, 0};
  for (uint32_t i = 0; i < 6; ++i)
    m.triangles.insert(m.triangles.end(), {6u, i, (i + 1) % 6});
  return m;
}

vrs::Mesh tetrahedron() {
  vrs::Mesh m;
  m.positions = {1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1}; // regular, centred at the origin
  m.triangles = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
  return m;
}

vrs::Mesh grid(int n, float jitter) {
  vrs::Mesh m;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) {
      bool inner = x > 0 && y > 0 && x < n && y < n;
      float jx = inner ? jitter * std::sin(float(x * 7 + y * 13)) : 0.0f;
      float jy = inner ? jitter * std::cos(float(x * 11 + y * 5)) : 0.0f;
      m.positions.insert(m.positions.end(), {float(x) + jx, float(y) + jy, 0.0f});
    }
  auto id = [n](int x, int y) { return uint32_t(y * (n + 1) + x); };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      m.triangles.insert(m.triangles.end(), {id(x, y), id(x + 1, y), id(x + 1, y + 1)});
      m.triangles.insert(m.triangles.end(), {id(x, y), id(x + 1, y + 1), id(x, y + 1)});
    }
  return m;
}

vrs::Mesh terrain(int n) {
  vrs::Mesh m = grid(n);
  for (size_t i = 0; i < m.positions.size(); i += 3) {
    float x = m.positions[i] / float(n), y = m.positions[i + 1] / float(n);
    m.positions[i + 2] =
        float(n) * 0.2f *
        (std::exp(-30 * ((x - 0.3f) * (x - 0.3f) + (y - 0.4f) * (y - 0.4f))) +
         0.6f * std::exp(-50 * ((x - 0.7f) * (x - 0.7f) + (y - 0.7f) * (y - 0.7f))) +
         0.05f * std::sin(12 * x) * std::cos(9 * y));
  }
  return m;
}

std::vector<NamedMesh> comparison_meshes() {
  std::vector<NamedMesh> meshes = {{"terrain", terrain(40)}, {"icosphere", icosphere(4)}};
  for (const char* name : {"elephant", "fandisk", "mushroom"}) {
    const std::string path = cgal_mesh(std::string(name) + ".off");
    if (!path.empty()) meshes.push_back({name, read_off(path)});
  }
  return meshes;
}

std::vector<int> compared_thread_counts() {
  const char* listed = std::getenv("VRS_TEST_THREAD_COUNTS");
  if (!listed || !*listed) return {2, 3, 8};
  std::vector<int> counts;
  for (const char* p = listed; *p;) {
    char* end = nullptr;
    const long n = std::strtol(p, &end, 10);
    if (end == p) break;
    if (n > 1) counts.push_back(int(n));
    p = *end == ',' ? end + 1 : end;
  }
  return counts.empty() ? std::vector<int>{2, 3, 8} : counts;
}

vrs::Mesh icosphere(int level) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  vrs::Mesh m;
  m.positions = {-1, t,  0,  1, t, 0,  -1, -t, 0,  1, -t, 0, 0,  -1, t,  0,  1, t,
                 0,  -1, -t, 0, 1, -t, t,  0,  -1, t, 0,  1, -t, 0,  -1, -t, 0, 1};
  m.triangles = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                 4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                 6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
  auto normalize = [&](uint32_t v) {
    float* p = &m.positions[3 * v];
    float l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (int c = 0; c < 3; ++c)
      p[c] /= l;
  };
  for (uint32_t v = 0; v < 12; ++v)
    normalize(v);
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      uint32_t v = uint32_t(m.positions.size() / 3);
      for (int c = 0; c < 3; ++c)
        m.positions.push_back((m.positions[3 * a + c] + m.positions[3 * b + c]) / 2);
      normalize(v);
      mid[key] = v;
      return v;
    };
    std::vector<uint32_t> next;
    for (size_t i = 0; i < m.triangles.size(); i += 3) {
      uint32_t a = m.triangles[i], b = m.triangles[i + 1], c = m.triangles[i + 2];
      uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    m.triangles = next;
  }
  return m;
}

vrs::Mesh plate_with_holes(int nx, int ny, const std::vector<std::pair<int, int>>& holes,
                           float thickness, int wall_rows) {
  auto solid = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= nx || y >= ny) return false;
    for (const auto& h : holes)
      if (h.first == x && h.second == y) return false;
    return true;
  };
  vrs::Mesh m;
  std::map<std::array<int, 3>, uint32_t> index; // (x, y, row) -> vertex, row 0 bottom
  auto vertex = [&](int x, int y, int row) {
    auto [it, fresh] = index.insert({{x, y, row}, uint32_t(m.vertex_count())});
    if (fresh)
      m.positions.insert(m.positions.end(),
                         {float(x), float(y), thickness * float(row) / float(wall_rows)});
    return it->second;
  };
  // A triangle facing `out` (its corners' order is chosen by that).
  auto triangle = [&](uint32_t a, uint32_t b, uint32_t c, const std::array<float, 3>& out) {
    const float* p = m.positions.data();
    float u[3], w[3];
    for (int k = 0; k < 3; ++k)
      u[k] = p[3 * b + k] - p[3 * a + k], w[k] = p[3 * c + k] - p[3 * a + k];
    const float n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                        u[0] * w[1] - u[1] * w[0]};
    if (n[0] * out[0] + n[1] * out[1] + n[2] * out[2] < 0) std::swap(b, c);
    m.triangles.insert(m.triangles.end(), {a, b, c});
  };
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      if (!solid(x, y)) continue;
      for (int side = 0; side < 2; ++side) { // bottom, top
        const int row = side * wall_rows;
        const std::array<float, 3> out{0, 0, side ? 1.0f : -1.0f};
        triangle(vertex(x, y, row), vertex(x + 1, y, row), vertex(x + 1, y + 1, row), out);
        triangle(vertex(x, y, row), vertex(x + 1, y + 1, row), vertex(x, y + 1, row), out);
      }
      // Walls where the next cell is a hole or outside: from (x0, y0) to (x1, y1), facing out.
      const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
      for (int d = 0; d < 4; ++d) {
        if (solid(x + dx[d], y + dy[d])) continue;
        int x0, y0, x1, y1;
        if (dx[d] != 0) {
          x0 = x1 = dx[d] > 0 ? x + 1 : x;
          y0 = y, y1 = y + 1;
        } else {
          y0 = y1 = dy[d] > 0 ? y + 1 : y;
          x0 = x, x1 = x + 1;
        }
        const std::array<float, 3> out{float(dx[d]), float(dy[d]), 0};
        for (int r = 0; r < wall_rows; ++r) {
          triangle(vertex(x0, y0, r), vertex(x1, y1, r), vertex(x1, y1, r + 1), out);
          triangle(vertex(x0, y0, r), vertex(x1, y1, r + 1), vertex(x0, y0, r + 1), out);
        }
      }
    }
  return m;
}

vrs::Mesh cracked_cylinder(int bands, int rows, int n) {
  vrs::Mesh m;
  const float h = 0.25f, pi = 3.14159265f;
  auto add = [&](int k, int of, float y) {
    const float a = 2 * pi * float(k) / float(of);
    m.positions.insert(m.positions.end(), {std::cos(a), y, std::sin(a)});
    return uint32_t(m.vertex_count() - 1);
  };
  std::vector<std::vector<uint32_t>> edge_rows(size_t(bands) + 1);
  for (int b = 0; b <= bands; ++b)
    for (int k = 0; k < 2 * n; ++k)
      edge_rows[size_t(b)].push_back(add(k, 2 * n, float(b * rows) * h));
  for (int b = 0; b < bands; ++b) {
    const int cols = b % 2 ? n : 2 * n, step = 2 * n / cols;
    std::vector<std::vector<uint32_t>> row(size_t(rows) + 1);
    for (int r = 0; r <= rows; ++r)
      for (int k = 0; k < cols; ++k)
        row[size_t(r)].push_back(r == 0      ? edge_rows[size_t(b)][size_t(k * step)]
                                 : r == rows ? edge_rows[size_t(b) + 1][size_t(k * step)]
                                             : add(k, cols, float(b * rows + r) * h));
    for (int r = 0; r < rows; ++r)
      for (int k = 0; k < cols; ++k) {
        const uint32_t a = row[size_t(r)][size_t(k)], c = row[size_t(r)][size_t((k + 1) % cols)],
                       d = row[size_t(r) + 1][size_t(k)],
                       e = row[size_t(r) + 1][size_t((k + 1) % cols)];
        m.triangles.insert(m.triangles.end(), {a, d, c, c, d, e});
      }
  }
  return m;
}

} // namespace vrs_test
