#include "output.h"

#include <algorithm>

#include "simplifier.h"

namespace vrs {

void write_output(Mesh& mesh, const SpatialOrder& order, const std::vector<uint8_t>& removed,
                  const SlotRecords& records, Report& rep) {
  const size_t n = mesh.vertex_count();
  auto& pos = mesh.positions;
  const auto& face_source = records.face_source;
  const auto& corner_source = records.corner_source;
  const auto& face_bound = records.face_bound;
  rep.remap.assign(n, kRemoved);
  std::vector<uint32_t> out_index(n, kRemoved); // internal vertex -> output index
  std::vector<float> kept;
  kept.reserve(pos.size());
  uint32_t next = 0;
  for (size_t i = 0; i < n; ++i) {
    const uint32_t v = order.vertex_new[i];
    if (removed[v]) continue;
    kept.insert(kept.end(), &pos[3 * size_t(v)], &pos[3 * size_t(v)] + 3);
    rep.remap[i] = out_index[v] = next++;
  }
  pos.swap(kept);
  std::vector<float>().swap(kept);

  auto& tris = mesh.triangles;
  const size_t slots = tris.size() / 3;
  std::vector<uint32_t> slot_of(slots); // input slot -> internal slot
  for (size_t f = 0; f < slots; ++f)
    slot_of[order.face_old[f]] = uint32_t(f);
  std::vector<uint32_t> out;
  out.reserve(tris.size());
  rep.face_source.clear();
  rep.corner_source.clear();
  for (size_t j = 0; j < slots; ++j) {
    const size_t f = slot_of[j];
    if (tris[3 * f] == kNone) continue;
    rep.face_source.push_back(face_source[f]);
    if (!face_bound.empty()) rep.error_bound = std::max(rep.error_bound, double(face_bound[f]));
    if (!corner_source.empty())
      rep.corner_source.insert(rep.corner_source.end(), &corner_source[3 * f],
                               &corner_source[3 * f] + 3);
    for (int c = 0; c < 3; ++c) {
      uint32_t v = tris[3 * f + c];
      if (!records.corners.empty()) { // welded: the copy the input corner had
        const uint32_t own = records.corners[corner_source[3 * f + c]];
        if (order.vertex_new[records.standing[own]] == v) v = order.vertex_new[own];
      }
      out.push_back(out_index[v]);
    }
  }
  tris.swap(out);
  rep.faces = tris.size() / 3;
  rep.vertices = next;
}

std::string input_warnings(const Report& r) {
  std::string w;
  auto add = [&](size_t count, const char* what) {
    if (!count) return;
    if (!w.empty()) w += "; ";
    w += std::to_string(count) + " " + what;
  };
  add(r.dropped_degenerate_faces, "faces with a repeated vertex dropped");
  add(r.reoriented_faces, "faces reversed to agree with their neighbours' orientation");
  add(r.nonfinite_vertices, "vertices with NaN/inf coordinates kept with their neighbours");
  add(r.kept_nonmanifold, "non-manifold vertices kept");
  add(r.kept_high_valence, "vertices of too high valence kept");
  add(r.unreferenced_vertices, "unreferenced vertices left untouched");
  return w;
}

void Simplifier::compact() {
  std::vector<uint8_t> removed(flags_.size());
  for (size_t v = 0; v < flags_.size(); ++v)
    removed[v] = flags_[v] & kFlagRemoved;
  // A welded copy goes where the copy standing for it goes.
  for (size_t i = 0; i < welding_.rep.size(); ++i)
    removed[order_.vertex_new[i]] = removed[order_.vertex_new[welding_.rep[i]]];
  write_output(mesh_, order_, removed,
               {face_source_, corner_source_, face_bound_, welding_.corners, welding_.rep}, rep_);
  if (!opt_.corner_sources) std::vector<uint32_t>().swap(rep_.corner_source);
}

} // namespace vrs
