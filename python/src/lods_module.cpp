// vrsimplify._core's levels of detail: lods() runs the nested chain (vrs/lods.h), write_glb()
// writes one (vrs/glb.h). python/vrsimplify/lods.py is the Python side.
#include <optional>
#include <string>
#include <vector>

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "core_arrays.h"
#include "vrs/glb.h"
#include "vrs/lods.h"

namespace nb = nanobind;

namespace {

using vrs_py::AnyArray;

nb::tuple lods(AnyArray vertices, AnyArray faces, std::vector<double> ratios,
               const std::string& mode, int threads, bool simplify_boundary, bool keep_boundary,
               double max_jump, double feature_angle, std::optional<AnyArray> seams,
               std::optional<AnyArray> corner_keys) {
  vrs::Options opt = vrs_py::make_options({"ratio", 1.0}, 0.0, mode, threads, simplify_boundary,
                                          keep_boundary, max_jump, feature_angle);
  vrs_py::RunInput in = vrs_py::read_run_input(vertices, faces, seams ? &*seams : nullptr,
                                               corner_keys ? &*corner_keys : nullptr);
  if (!in.seams.empty()) opt.constrained_edges = &in.seams;
  const vrs::Mesh& mesh = in.mesh;
  const double diagonal = vrs::bounding_box_diagonal(mesh);
  vrs::LodChain chain;
  {
    nb::gil_scoped_release release;
    chain = vrs::simplify_lods(mesh, ratios, opt, in.has_keys ? &in.keys : nullptr);
  }
  if (!chain.ok) throw nb::value_error(chain.message.c_str());
  nb::list levels;
  for (vrs::LodLevel& l : chain.levels) {
    const size_t f = l.triangles.size() / 3;
    levels.append(nb::make_tuple(l.ratio, l.vertex_count,
                                 vrs_py::to_numpy(std::move(l.triangles), {f, 3}),
                                 vrs_py::to_numpy(vrs_py::signed_indices(l.face_source), {f}),
                                 vrs_py::to_numpy(vrs_py::signed_indices(l.corner_source), {f, 3}),
                                 vrs_py::report_dict(l.report, false, 0.0, diagonal)));
  }
  std::vector<int64_t> order(chain.vertices.begin(), chain.vertices.end());
  const size_t m = order.size();
  return nb::make_tuple(vrs_py::to_numpy(std::move(order), {m}), levels);
}

// Per-vertex or per-corner rows of `columns` floats, or nothing.
std::vector<float> rows(const std::optional<AnyArray>& a, size_t count, size_t columns,
                        const char* what) {
  if (!a) return {};
  return vrs_py::read_floats(*a, count, columns, what);
}

nb::dict write_glb(const std::string& path, AnyArray vertices, AnyArray order,
                   std::vector<double> ratios, std::vector<size_t> vertex_counts,
                   std::vector<AnyArray> level_faces, std::vector<AnyArray> corner_sources,
                   std::optional<AnyArray> normals, std::optional<AnyArray> colors,
                   std::optional<AnyArray> uvs, std::optional<AnyArray> corner_normals,
                   std::optional<AnyArray> corner_colors, std::optional<AnyArray> corner_uvs,
                   const std::string& texture, std::vector<double> level_errors, size_t input_faces,
                   bool compress) {
  const std::vector<float> positions = vrs_py::read_positions(vertices);
  const size_t n = positions.size() / 3;
  vrs::LodChain chain;
  chain.ok = true;
  chain.vertices = vrs_py::read_vector(order, n, "order");
  const size_t m = chain.vertices.size();
  for (size_t k = 0; k < ratios.size(); ++k) {
    vrs::LodLevel l;
    l.ratio = ratios[k];
    l.vertex_count = vertex_counts[k];
    if (l.vertex_count > m) throw nb::value_error("a level's vertex count exceeds the order");
    l.triangles = vrs_py::read_indices(level_faces[k], l.vertex_count, "level face", 3);
    if (k < corner_sources.size())
      l.corner_source =
          vrs_py::read_indices(corner_sources[k], 3 * input_faces, "corner source", 3);
    chain.levels.push_back(std::move(l));
  }
  const std::vector<float> vn = rows(normals, n, 3, "normals"), vc = rows(colors, n, 4, "colors"),
                           vt = rows(uvs, n, 2, "uvs"),
                           cn = rows(corner_normals, 3 * input_faces, 3, "corner_normals"),
                           cc = rows(corner_colors, 3 * input_faces, 4, "corner_colors"),
                           ct = rows(corner_uvs, 3 * input_faces, 2, "corner_uvs");
  vrs::GlbAttributes a;
  auto ptr = [](const std::vector<float>& v) { return v.empty() ? nullptr : v.data(); };
  a.normals = ptr(vn), a.colors = ptr(vc), a.uvs = ptr(vt);
  a.corner_normals = ptr(cn), a.corner_colors = ptr(cc), a.corner_uvs = ptr(ct);
  a.texture_uri = texture;
  a.level_errors = level_errors;
  a.compress = compress;
  a.generator = std::string("vrsimplify ") + VRS_VERSION;
  vrs::GlbLayout layout;
  const std::string err = vrs::write_glb(path, positions.data(), n, chain, a, &layout);
  if (!err.empty()) throw nb::value_error(err.c_str());
  nb::dict d;
  d["file_bytes"] = layout.file_bytes;
  d["gltf_vertices"] = layout.vertex_count;
  d["vertex_stride"] = layout.vertex_stride;
  d["compressed"] = layout.compressed;
  nb::list levels;
  for (const auto& L : layout.levels) {
    nb::dict x;
    x["faces"] = L.faces;
    x["vertices"] = L.vertex_count;
    x["bytes_to_draw"] = L.bytes_to_draw;
    x["index_offset"] = L.index_offset;
    x["index_bytes"] = L.index_bytes;
    levels.append(x);
  }
  d["levels"] = levels;
  return d;
}

} // namespace

void register_lods(nb::module_& m) {
  m.def("lods", &lods, nb::arg("vertices"), nb::arg("faces"), nb::arg("ratios"), nb::arg("mode"),
        nb::arg("threads"), nb::arg("simplify_boundary"), nb::arg("keep_boundary"),
        nb::arg("max_jump"), nb::arg("feature_angle"), nb::arg("seams").none(),
        nb::arg("corner_keys").none());
  m.def("write_glb", &write_glb, nb::arg("path"), nb::arg("vertices"), nb::arg("order"),
        nb::arg("ratios"), nb::arg("vertex_counts"), nb::arg("level_faces"),
        nb::arg("corner_sources"), nb::arg("normals").none(), nb::arg("colors").none(),
        nb::arg("uvs").none(), nb::arg("corner_normals").none(), nb::arg("corner_colors").none(),
        nb::arg("corner_uvs").none(), nb::arg("texture"), nb::arg("level_errors"),
        nb::arg("input_faces"), nb::arg("compress"));
}
