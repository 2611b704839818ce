// The progressive .glb (glb.h, docs/progressive.md): the base mesh as a glTF primitive, then
// the insertion records as one byte stream the primitive's extension names.
#include <algorithm>

#include "glb_file.h"
#include "glb_json.h"
#include "progressive_order.h"
#include "progressive_record.h"
#include "vertex_table.h"
#include "vrs/glb.h"

namespace vrs {

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
  RecordWriter records(p, input_triangles, per_corner, table, base);
  // Records reordered within a hundredth of them: each batch's in the order of where they are,
  // so that each names its patch by a short step from the last.
  const size_t window = std::max<size_t>(256, p.insertion_count() / 100);
  std::vector<uint8_t> stream;
  std::vector<std::pair<int64_t, uint32_t>> keyed;
  for (const std::vector<uint32_t>& batch :
       insertion_batches(p, input_triangles, vertex_count, window)) {
    keyed.clear();
    for (uint32_t r : batch)
      keyed.push_back({records.newest_patch_face(r), r});
    std::stable_sort(keyed.begin(), keyed.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& kr : keyed)
      if (!records.write(kr.second, stream)) return nonfinite;
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
  j.primitive_extension("VRS_mesh_progressive",
                        "{\"version\":3,\"bufferView\":" + num(size_t(stream_view)) +
                            ",\"insertions\":" + num(p.insertion_count()) + ",\"vertexCount\":" +
                            num(table.size()) + ",\"faceCount\":" + num(records.faces()) + "}");
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
    layout->faces = records.faces();
    layout->insertions = p.insertion_count();
    layout->vertex_stride = table.stride();
    layout->stream_offset = bin_start + stream_at;
    layout->stream_bytes = stream.size();
    layout->record_topology_bytes = records.topology_bytes();
  }
  return "";
}

} // namespace vrs
