// vrsimplify._core's progressive mesh: progressive() runs one recorded simplification
// (vrs/progressive.h). python/vrsimplify/progressive.py is the Python side.
#include <optional>
#include <string>
#include <vector>

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>

#include "core_arrays.h"
#include "vrs/progressive.h"

namespace nb = nanobind;

namespace {

using vrs_py::AnyArray;

std::vector<int64_t> wide(const std::vector<uint32_t>& v) {
  return std::vector<int64_t>(v.begin(), v.end());
}

nb::tuple progressive(AnyArray vertices, AnyArray faces, double base, const std::string& mode,
                      bool simplify_boundary, bool keep_boundary, double max_jump,
                      double feature_angle, std::optional<AnyArray> seams,
                      std::optional<AnyArray> corner_keys) {
  vrs::Options opt = vrs_py::make_options({"ratio", base}, 0.0, mode, 1, simplify_boundary,
                                          keep_boundary, max_jump, feature_angle);
  vrs_py::RunInput in = vrs_py::read_run_input(vertices, faces, seams ? &*seams : nullptr,
                                               corner_keys ? &*corner_keys : nullptr);
  if (!in.seams.empty()) opt.constrained_edges = &in.seams;
  const vrs::Mesh& mesh = in.mesh;
  const double diagonal = vrs::bounding_box_diagonal(mesh);
  vrs::ProgressiveMesh p;
  {
    nb::gil_scoped_release release;
    p = vrs::simplify_progressive(mesh, opt, in.has_keys ? &in.keys : nullptr);
  }
  if (!p.ok) throw nb::value_error(p.message.c_str());
  const size_t b = p.base_slots.size(), r = p.vertex.size(), w = p.slots.size();
  return nb::make_tuple(
      vrs_py::to_numpy(wide(p.base_slots), {b}), vrs_py::to_numpy(wide(p.base_corners), {b, 3}),
      vrs_py::to_numpy(wide(p.vertex), {r}), vrs_py::to_numpy(wide(p.first), {r + 1}),
      vrs_py::to_numpy(wide(p.slots), {w}), vrs_py::to_numpy(wide(p.corners), {w, 3}),
      vrs_py::report_dict(p.report, false, 0.0, diagonal));
}

} // namespace

void register_progressive(nb::module_& m) {
  m.def("progressive", &progressive, nb::arg("vertices"), nb::arg("faces"), nb::arg("base"),
        nb::arg("mode"), nb::arg("simplify_boundary"), nb::arg("keep_boundary"),
        nb::arg("max_jump"), nb::arg("feature_angle"), nb::arg("seams").none(),
        nb::arg("corner_keys").none());
}
