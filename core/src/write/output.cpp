#include "write/output.h"

#include <algorithm>

namespace vrs {

namespace {

// Blocks of consecutive input indices: each counts what it keeps, a prefix over the blocks says
// where each writes, and the blocks then write at once (the same output on any threads).
constexpr size_t kBlock = 65536;

// starts[b]: where block b of [0, n) writes, from kept(i) over the indices; starts[blocks]: all.
template <class Kept>
std::vector<uint32_t> block_starts(Workers* workers, size_t n, const Kept& kept) {
  std::vector<uint32_t> starts((n + kBlock - 1) / kBlock + 1, 0);
  for_each_block(workers, n, kBlock, [&](size_t begin, size_t end) {
    uint32_t count = 0;
    for (size_t i = begin; i < end; ++i)
      count += kept(i);
    starts[begin / kBlock + 1] = count;
  });
  for (size_t b = 1; b < starts.size(); ++b)
    starts[b] += starts[b - 1];
  return starts;
}

} // namespace

void write_output(Mesh& mesh, const SpatialOrder& order, const std::vector<uint8_t>& removed,
                  const SlotRecords& records, Report& rep, Workers* workers) {
  const size_t n = mesh.vertex_count();
  auto& pos = mesh.positions;
  const auto& kept_faces = records.kept_faces;
  const auto& corner_source = records.corner_source;
  const auto& face_bound = records.face_bound;
  rep.remap.assign(n, kRemoved);
  std::vector<uint32_t> out_index(n, kRemoved); // internal vertex -> output index
  const auto vstarts =
      block_starts(workers, n, [&](size_t i) { return !removed[order.vertex_new[i]]; });
  std::vector<float> kept(3 * size_t(vstarts.back()));
  for_each_block(workers, n, kBlock, [&](size_t begin, size_t end) {
    uint32_t next = vstarts[begin / kBlock];
    for (size_t i = begin; i < end; ++i) {
      const uint32_t v = order.vertex_new[i];
      if (removed[v]) continue;
      std::copy_n(&pos[3 * size_t(v)], 3, &kept[3 * size_t(next)]);
      rep.remap[i] = out_index[v] = next++;
    }
  });
  pos.swap(kept);
  std::vector<float>().swap(kept);

  auto& tris = mesh.triangles;
  const size_t slots = tris.size() / 3;
  std::vector<uint32_t> slot_of(slots); // input slot -> internal slot
  for_each_block(workers, slots, kBlock, [&](size_t begin, size_t end) {
    for (size_t f = begin; f < end; ++f)
      slot_of[order.face_old[f] & ~kRewrittenSlot] = uint32_t(f);
  });
  const auto fstarts =
      block_starts(workers, slots, [&](size_t j) { return tris[3 * size_t(slot_of[j])] != kNone; });
  const size_t faces = fstarts.back();
  std::vector<uint32_t> out(3 * faces);
  rep.face_source.assign(faces, 0);
  rep.corner_source.assign(corner_source.empty() ? 0 : 3 * faces, 0);
  const Constraints* constraints = records.constraints;
  rep.constrained_sides.assign(constraints ? faces : 0, 0);
  std::vector<float> bound(fstarts.size() - 1, 0.0f); // each block's largest
  for_each_block(workers, slots, kBlock, [&](size_t begin, size_t end) {
    const size_t b = begin / kBlock;
    size_t at = fstarts[b];
    for (size_t j = begin; j < end; ++j) {
      const size_t f = slot_of[j];
      if (tris[3 * f] == kNone) continue;
      const uint32_t old = order.face_old[f];
      rep.face_source[at] = old & kRewrittenSlot ? kRemoved
                            : kept_faces.empty() ? old
                                                 : kept_faces[old];
      if (!face_bound.empty()) bound[b] = std::max(bound[b], face_bound[f]);
      if (!corner_source.empty()) std::copy_n(&corner_source[3 * f], 3, &rep.corner_source[3 * at]);
      if (constraints)
        for (int c = 0; c < 3; ++c)
          rep.constrained_sides[at] |=
              uint8_t(constraints->has(tris[3 * f + c], tris[3 * f + (c + 1) % 3]) << c);
      for (int c = 0; c < 3; ++c) {
        uint32_t v = tris[3 * f + c];
        if (!records.corners.empty()) { // welded: the copy the input corner had
          const uint32_t own = records.corners[corner_source[3 * f + c]];
          if (order.vertex_new[records.standing[own]] == v) v = order.vertex_new[own];
        }
        out[3 * at + c] = out_index[v];
      }
      if (!records.turned.empty() && records.turned[corner_source[3 * f] / 3]) {
        std::swap(out[3 * at + 1], out[3 * at + 2]); // welded: corner sources are kept
        std::swap(rep.corner_source[3 * at + 1], rep.corner_source[3 * at + 2]);
        if (constraints) { // sides (0 1, 1 2, 2 0) become (0 2, 2 1, 1 0)
          const uint8_t s = rep.constrained_sides[at];
          rep.constrained_sides[at] = uint8_t((s >> 2 & 1) | (s & 2) | (s & 1) << 2);
        }
      }
      ++at;
    }
  });
  for (float x : bound)
    rep.error_bound = std::max(rep.error_bound, double(x));
  tris.swap(out);
  rep.faces = tris.size() / 3;
  rep.vertices = vstarts.back();
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

} // namespace vrs
