// The progressive .glb (glb.h, docs/progressive.md): the base mesh as a glTF primitive, then
// the insertion records as one byte stream the primitive's extension names.
#include <algorithm>
#include <array>

#include "glb_file.h"
#include "glb_json.h"
#include "vertex_table.h"
#include "vrs/glb.h"

namespace vrs {

namespace {

constexpr uint32_t kNoSlot = 0xffffffffu;

// A record's shapes: its faces (apex, ring[i], ring[i + 1]) around a fan whose ring is the
// patch's outline (closed, or open: all of it but one side), or around a ring it lists, or
// each face's three corners as they are (a fan broken by a seam's copies).
enum Shape : uint32_t { kCorners = 0, kClosedFan = 1, kOpenFan = 2, kListedRing = 3 };

void put_varint(std::vector<uint8_t>& out, uint64_t x) {
  while (x >= 0x80) {
    out.push_back(uint8_t(x | 0x80));
    x >>= 7;
  }
  out.push_back(uint8_t(x));
}

using Face = std::array<uint32_t, 3>;

// The faces of one record ordered around their common vertex `apex`, each rotated to start at
// it: false when they are no single fan.
bool as_fan(std::vector<Face>& faces, std::vector<uint32_t>& order, uint32_t apex, bool& closed) {
  const size_t k = faces.size();
  for (Face& f : faces) {
    const int at = f[0] == apex ? 0 : f[1] == apex ? 1 : f[2] == apex ? 2 : -1;
    if (at < 0) return false;
    std::rotate(f.begin(), f.begin() + at, f.end());
  }
  // The first face: one whose first ring vertex no other face ends at (an open fan's end).
  size_t start = 0;
  for (size_t i = 0; i < k; ++i) {
    bool follows = false;
    for (size_t j = 0; j < k && !follows; ++j)
      follows = j != i && faces[j][2] == faces[i][1];
    if (!follows) {
      start = i;
      break;
    }
  }
  order.assign(1, uint32_t(start));
  std::vector<uint8_t> used(k, 0);
  used[start] = 1;
  while (order.size() < k) {
    const uint32_t end = faces[order.back()][2];
    size_t next = k;
    for (size_t j = 0; j < k && next == k; ++j)
      if (!used[j] && faces[j][1] == end) next = j;
    if (next == k) return false;
    used[next] = 1;
    order.push_back(uint32_t(next));
  }
  closed = k >= 3 && faces[order.back()][2] == faces[order.front()][1];
  return true;
}

} // namespace

std::string write_progressive_glb(const std::string& path, const float* positions,
                                  size_t vertex_count, const std::vector<uint32_t>& input_triangles,
                                  const ProgressiveMesh& p, const GlbAttributes& a,
                                  ProgressiveLayout* layout) {
  if (!p.ok) return "no progressive mesh to write";
  if (a.compress) return "a progressive .glb is written without EXT_meshopt_compression";
  if (p.base_slots.empty()) return "the base mesh has no faces: glTF needs at least one";
  const size_t slot_count = input_triangles.size() / 3;
  for (const auto* corners : {&p.base_corners, &p.corners})
    for (uint32_t c : *corners)
      if (c >= input_triangles.size() || input_triangles[c] >= vertex_count)
        return "a corner names a vertex the mesh does not have";
  for (uint32_t s : p.slots)
    if (s >= slot_count) return "a record names a slot the mesh does not have";
  const bool per_corner = a.corner_normals || a.corner_colors || a.corner_uvs;
  VertexTable table(positions, vertex_count, a);
  auto vertex_of = [&](uint32_t corner, uint32_t& out) {
    return table.find_or_add(input_triangles[corner], per_corner ? corner : kNoRecord, out);
  };
  const char* nonfinite =
      "a face has a vertex with a non-finite coordinate, which glTF cannot hold";

  // The base: its faces in slot order, its vertices as they are first used.
  std::vector<uint32_t> base(p.base_corners.size());
  for (size_t i = 0; i < base.size(); ++i)
    if (!vertex_of(p.base_corners[i], base[i])) return nonfinite;
  table.order_since_by_use(0, base);
  const size_t base_vertices = table.size();
  const float bounds[6] = {table.low()[0],  table.low()[1],  table.low()[2],
                           table.high()[0], table.high()[1], table.high()[2]};
  // The decoder's slots: the base's faces first, then each face a record adds at the end.
  std::vector<uint32_t> slot_at(slot_count, kNoSlot); // input slot -> decoder slot
  for (size_t i = 0; i < p.base_slots.size(); ++i)
    slot_at[p.base_slots[i]] = uint32_t(i);
  std::vector<uint32_t> live = base; // the decoder's faces, 3 a slot

  std::vector<uint8_t> stream;
  size_t topology_bytes = 0;
  std::vector<Face> faces, turned;
  std::vector<uint32_t> order, input_slot, patch_slots, patch, refs, ring;
  for (size_t r = 0; r < p.insertion_count(); ++r) {
    const size_t before = table.size(), record_start = stream.size();
    faces.clear();
    input_slot.clear();
    for (uint32_t j = p.first[r]; j < p.first[r + 1]; ++j) {
      Face f;
      for (int c = 0; c < 3; ++c)
        if (!vertex_of(p.corners[3 * size_t(j) + c], f[c])) return nonfinite;
      faces.push_back(f);
      input_slot.push_back(p.slots[j]);
    }
    const size_t k = faces.size(), added = table.size() - before;
    // The patch this record replaces: the faces now in its slots.
    const size_t live_faces = live.size() / 3;
    patch_slots.clear();
    patch.clear();
    for (uint32_t s : input_slot)
      if (slot_at[s] != kNoSlot) {
        patch_slots.push_back(slot_at[s]);
        for (int c = 0; c < 3; ++c)
          patch.push_back(live[3 * size_t(slot_at[s]) + c]);
      }
    // The apex: a vertex of every face (the inserted vertex, unless a seam gave it copies).
    uint32_t apex = kNoSlot;
    for (int c = 0; c < 3 && apex == kNoSlot; ++c) {
      const uint32_t v = faces[0][c];
      bool everywhere = true;
      for (const Face& f : faces)
        everywhere = everywhere && (f[0] == v || f[1] == v || f[2] == v);
      if (everywhere) apex = v;
    }
    Shape shape = kCorners;
    bool closed = false;
    turned = faces;
    if (apex != kNoSlot && as_fan(turned, order, apex, closed)) {
      shape = kListedRing;
      ring.clear();
      for (uint32_t i : order)
        ring.push_back(turned[i][1]);
      if (!closed) ring.push_back(turned[order.back()][2]);
      // The ring as the patch's outline gives it (each outline side once, the patch's way).
      const size_t sides = closed ? k : k + 1;
      if (patch.size() == 3 * (sides - 2)) {
        bool outline = true;
        for (size_t i = 0; i < sides && outline; ++i) {
          const uint32_t from = ring[i], to = ring[(i + 1) % sides];
          int found = 0;
          for (size_t t = 0; t < patch.size(); t += 3)
            for (int c = 0; c < 3; ++c) {
              const uint32_t a = patch[t + c], b = patch[t + (c + 1) % 3];
              if (a == from && b == to) ++found;
              if (a == to && b == from) found = 99; // an inner side: not the outline
            }
          outline = found == 1;
        }
        if (outline) shape = closed ? kClosedFan : kOpenFan;
      }
      std::vector<Face> sorted;
      std::vector<uint32_t> slots;
      for (uint32_t i : order)
        sorted.push_back(turned[i]), slots.push_back(input_slot[i]);
      faces.swap(sorted);
      input_slot.swap(slots);
    }
    // A vertex reference: one the record adds, a corner of the patch, or an older vertex.
    auto ref = [&](uint32_t v) -> uint64_t {
      if (v >= before) return v - before;
      for (size_t i = 0; i < patch.size(); ++i)
        if (patch[i] == v) return added + i;
      return added + patch.size() + (before - 1 - v);
    };
    const bool regular = shape != kCorners && added == 1 && apex == before;
    put_varint(stream, uint64_t(k) << 3 | shape << 1 | !regular);
    if (!regular) {
      put_varint(stream, added);
      if (shape != kCorners) put_varint(stream, ref(apex));
    }
    const size_t vertex_bytes_at = stream.size();
    stream.insert(stream.end(), table.bytes().begin() + before * table.stride(),
                  table.bytes().end());
    const size_t vertex_bytes = stream.size() - vertex_bytes_at;
    if (shape == kCorners || shape == kListedRing) put_varint(stream, patch_slots.size());
    for (uint32_t s : patch_slots) // how far back from the last face
      put_varint(stream, uint64_t(live_faces) - 1 - s);
    if (shape == kClosedFan || shape == kOpenFan) {
      put_varint(stream, ref(ring[0]));
    } else if (shape == kListedRing) {
      put_varint(stream, ring.size() - k); // 0: closed, 1: open
      for (uint32_t v : ring)
        put_varint(stream, ref(v));
    } else {
      for (const Face& f : faces)
        for (uint32_t v : f)
          put_varint(stream, ref(v));
    }
    topology_bytes += stream.size() - record_start - vertex_bytes;
    // As the decoder does: the faces in order into the patch's slots, the rest at the end.
    for (size_t i = 0; i < k; ++i) {
      uint32_t s;
      if (i < patch_slots.size()) {
        s = patch_slots[i];
        std::copy(faces[i].begin(), faces[i].end(), live.begin() + 3 * size_t(s));
      } else {
        s = uint32_t(live.size() / 3);
        live.insert(live.end(), faces[i].begin(), faces[i].end());
      }
      slot_at[input_slot[i]] = s;
    }
  }

  bool wide = false;
  std::vector<uint8_t> ib = index_bytes(base, base_vertices, wide);
  std::vector<uint8_t> vb(table.bytes().begin(),
                          table.bytes().begin() + base_vertices * table.stride());
  const size_t vertex_at = ib.size(), stream_at = vertex_at + pad4(vb.size());
  GlbJson j(a, table.stride(), table.normal_at(), table.color_at(), table.uv_at());
  j.buffer(stream_at + pad4(stream.size()));
  const int vertex_view = j.view(vertex_at, vb.size(), table.stride(), 34962);
  const int index_view = j.view(0, base.size() * (wide ? 4 : 2), 0, 34963);
  const int stream_view = j.view(stream_at, stream.size(), 0, 0);
  auto num = [](size_t x) { return std::to_string(x); };
  j.primitive_extension("VRS_mesh_progressive", "{\"bufferView\":" + num(size_t(stream_view)) +
                                                    ",\"insertions\":" + num(p.insertion_count()) +
                                                    ",\"vertexCount\":" + num(table.size()) +
                                                    ",\"faceCount\":" + num(live.size() / 3) + "}");
  const double ratio = slot_count ? double(p.base_slots.size()) / double(slot_count) : 1.0;
  j.level(vertex_view, base_vertices, bounds, index_view, base.size(), wide, ratio, -1.0, 0);
  size_t json_bytes = 0;
  const std::string err = write_glb_file(path, j.finish(), {&ib, &vb, &stream}, &json_bytes);
  if (!err.empty()) return err;
  if (layout) {
    const size_t bin_start = 12 + 8 + json_bytes + 8;
    layout->file_bytes = bin_start + stream_at + pad4(stream.size());
    layout->base_bytes = bin_start + vertex_at + vb.size();
    layout->base_vertices = base_vertices;
    layout->base_faces = base.size() / 3;
    layout->vertex_count = table.size();
    layout->faces = live.size() / 3;
    layout->insertions = p.insertion_count();
    layout->vertex_stride = table.stride();
    layout->stream_offset = bin_start + stream_at;
    layout->stream_bytes = stream.size();
    layout->record_topology_bytes = topology_bytes;
  }
  return "";
}

} // namespace vrs
