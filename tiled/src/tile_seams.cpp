#include "tile_seams.h"

#include <algorithm>
#include <tuple>

#include "corner_values.h"

namespace vrs::tiled {

std::vector<uint32_t> tile_seams(const vrs::Mesh& mesh, const TileKeys& keys) {
  struct Side {
    uint32_t lo, hi, face;
    uint8_t lo_corner, hi_corner;
  };
  const size_t faces = mesh.face_count();
  std::vector<Side> sides;
  sides.reserve(3 * faces);
  for (uint32_t f = 0; f < faces; ++f)
    for (uint8_t c = 0; c < 3; ++c) {
      const uint8_t d = uint8_t((c + 1) % 3);
      const uint32_t u = mesh.triangles[3 * f + c], v = mesh.triangles[3 * f + d];
      if (u == v) continue;
      sides.push_back(u < v ? Side{u, v, f, c, d} : Side{v, u, f, d, c});
    }
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    return std::tie(x.lo, x.hi, x.face) < std::tie(y.lo, y.hi, y.face);
  });
  const auto differ = [&](uint32_t f, uint8_t c, uint32_t g, uint8_t d) {
    return !same_texcoord(keys.texcoords, keys.a[3 * f + c], keys.a[3 * g + d]) ||
           !same_normal(keys.normals, keys.b[3 * f + c], keys.b[3 * g + d], kNormalCreaseCos);
  };
  const auto flagged = [&](const Side& x) { // the side as written: from lo's corner or hi's
    const uint8_t c = (x.lo_corner + 1) % 3 == x.hi_corner ? x.lo_corner : x.hi_corner;
    return !keys.seam_sides.empty() && keys.seam_sides[x.face] >> c & 1;
  };
  std::vector<uint32_t> seams;
  for (size_t i = 0; i < sides.size();) {
    size_t j = i + 1;
    while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi)
      ++j;
    // Two faces on an edge: a seam where they disagree. A seam the level before kept stays
    // one, also where this tile holds one of its faces only (at the tile's border): the next
    // level, where both are in one tile again, may not tell it by values (two charts can agree
    // at both ends of it). A border edge needs nothing else; a non-manifold one is kept by the
    // core anyway.
    bool seam = false;
    for (size_t k = i; k < j && !seam; ++k)
      seam = flagged(sides[k]);
    if (!seam && j - i == 2) {
      const Side &s = sides[i], &t = sides[i + 1];
      seam = keys.group[s.face] != keys.group[t.face] ||
             differ(s.face, s.lo_corner, t.face, t.lo_corner) ||
             differ(s.face, s.hi_corner, t.face, t.hi_corner);
    }
    if (seam) seams.insert(seams.end(), {sides[i].lo, sides[i].hi});
    i = j;
  }
  return seams;
}

} // namespace vrs::tiled
