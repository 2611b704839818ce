#include "output_polygons.h"

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "tile_files.h"

namespace vrs::tiled {

OutputPolygons::OutputPolygons(const std::string& dir, const FaceSource& faces) {
  using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;
  File polygons(std::fopen((dir + "/polygons.bin").c_str(), "rb"), &std::fclose);
  PolygonRecord poly{};
  if (!polygons || std::fread(&poly, sizeof poly, 1, polygons.get()) != 1) return;
  faces([&](const FaceRecord& r) {
    if (!r.polygon) return;
    Corners& c = marked_[Key{{r.v[0], r.v[1], r.v[2]}}];
    for (int k = 0; k < 3; ++k)
      c.a[k] = r.a[k], c.b[k] = r.b[k];
  });
  if (marked_.empty()) return;
  File input(std::fopen((dir + "/faces.bin").c_str(), "rb"), &std::fclose);
  if (!input) throw std::runtime_error("cannot read the faces in " + dir);
  // The input's faces in order, each polygon's triangles read as they come.
  uint64_t face = 0;
  std::vector<Key> tris;
  std::vector<Corners*> found;
  do {
    tris.resize(poly.corners - 2);
    for (; face < poly.first; ++face) { // faces of no polygon
      Key skip;
      if (std::fread(skip.v, 12, 1, input.get()) != 1) return;
    }
    if (std::fread(tris.data(), 12, tris.size(), input.get()) != tris.size()) return;
    face += tris.size();
    found.clear();
    for (const Key& t : tris) {
      const auto it = marked_.find(t);
      if (it == marked_.end() || it->second.polygon != kNone) break;
      found.push_back(&it->second);
    }
    if (found.size() != tris.size()) continue; // a triangle of it was replaced
    // Corners 0 and 1 from its first triangle, then the third corner of each (the fan).
    const uint32_t p = uint32_t(first_.size() - 1);
    for (uint32_t k = 0; k < poly.corners; ++k) {
      const uint32_t t = k < 2 ? 0 : k - 2, c = k < 2 ? k : 2;
      v_.push_back(tris[t].v[c]);
      a_.push_back(found[t]->a[c]);
      b_.push_back(found[t]->b[c]);
    }
    first_.push_back(uint32_t(v_.size()));
    for (Corners* c : found)
      c->polygon = p;
    merged_ += poly.corners - 3;
  } while (std::fread(&poly, sizeof poly, 1, polygons.get()) == 1);
}

uint32_t OutputPolygons::of(const FaceRecord& r) const {
  if (!r.polygon) return kNone;
  const auto it = marked_.find(Key{{r.v[0], r.v[1], r.v[2]}});
  return it == marked_.end() ? kNone : it->second.polygon;
}

} // namespace vrs::tiled
