// vrsimplify._core: the C++ core behind the numpy API (python/vrsimplify/__init__.py holds the
// Python side: argument checks a user reads, the targets, the result type). Arrays are read
// through their strides straight into the core's mesh (the one copy an in-place core needs,
// which also leaves the caller's arrays untouched); the run releases the GIL; Ctrl-C and the
// progress callback are served from the progress hook, which takes the GIL back briefly.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>

#include "core_arrays.h"
#include "vrs/simplify.h"

namespace nb = nanobind;

namespace {

using namespace vrs_py;

// A boolean array of one entry per vertex or face, as bytes.
std::vector<uint8_t> read_mask(const AnyArray& a, size_t n, const char* what, const char* per) {
  if (a.ndim() != 1 || a.shape(0) != n || a.dtype() != nb::dtype<bool>())
    throw nb::value_error(
        (std::string(what) + " must be a boolean array of one entry per " + per).c_str());
  std::vector<uint8_t> out(n);
  const bool* base = static_cast<const bool*>(a.data());
  for (size_t i = 0; i < n; ++i)
    out[i] = base[int64_t(i) * a.stride(0)];
  return out;
}

nb::tuple simplify(AnyArray vertices, AnyArray faces, const std::string& target_kind,
                   double target_value, double max_error, const std::string& mode, int threads,
                   bool simplify_boundary, bool keep_boundary, double max_jump,
                   double feature_angle, std::optional<AnyArray> seams,
                   std::optional<AnyArray> locked, nb::object progress,
                   const std::string& split_vertices, std::optional<AnyArray> polygon_faces) {
  vrs::Options opt = make_options({target_kind, target_value}, max_error, mode, threads,
                                  simplify_boundary, keep_boundary, max_jump, feature_angle);
  if (split_vertices == "seam")
    opt.split_vertices = vrs::SplitVertices::Seam;
  else if (split_vertices == "weld")
    opt.split_vertices = vrs::SplitVertices::Weld;
  else if (split_vertices == "keep")
    opt.split_vertices = vrs::SplitVertices::Keep;
  else
    throw nb::value_error("split_vertices must be seam, weld or keep");
  vrs::Mesh mesh;
  mesh.positions = read_positions(vertices);
  const size_t n = mesh.vertex_count();
  mesh.triangles = read_indices(faces, n, "triangle", 3);
  std::vector<uint32_t> seam_pairs;
  if (seams) {
    seam_pairs = read_indices(*seams, n, "seam", 2);
    opt.constrained_edges = &seam_pairs;
  }
  std::vector<uint8_t> lock;
  if (locked) {
    lock = read_mask(*locked, n, "locked", "vertex");
    opt.locked = &lock;
  }
  std::vector<uint8_t> polygon; // the triangles of polygons the caller puts back whole
  if (polygon_faces) {
    polygon = read_mask(*polygon_faces, mesh.face_count(), "polygon_faces", "face");
    opt.polygon_faces = &polygon;
  }

  // Served every few hundred removals on this (the calling) thread: the GIL is taken only
  // here, so other Python threads run, and so may another simplification.
  bool python_error = false;
  opt.progress = [&](float fraction) -> bool {
    nb::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) {
      python_error = true;
      return false;
    }
    if (progress.is_none()) return true;
    try {
      // Any object Python calls true goes on (np.True_, 1, a non-empty string): as `if`.
      nb::object go_on = progress(fraction);
      if (go_on.is_none()) return true;
      const int truth = PyObject_IsTrue(go_on.ptr());
      if (truth < 0) throw nb::python_error();
      return truth != 0;
    } catch (nb::python_error& e) {
      e.restore();
      python_error = true;
      return false;
    }
  };

  vrs::Report report;
  const double diagonal = vrs::bounding_box_diagonal(mesh);
  const auto t0 = std::chrono::steady_clock::now();
  {
    nb::gil_scoped_release release;
    report = vrs::simplify(mesh, opt);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (python_error) throw nb::python_error(); // KeyboardInterrupt, or the callback's error
  if (!report.ok) throw nb::value_error(report.message.c_str());

  std::vector<int64_t> vertex_map(mesh.vertex_count());
  for (size_t v = 0; v < report.remap.size(); ++v)
    if (report.remap[v] != vrs::kRemoved) vertex_map[report.remap[v]] = int64_t(v);
  const size_t f = mesh.face_count(), m = vertex_map.size();
  return nb::make_tuple(to_numpy(std::move(mesh.triangles), {f, 3}),
                        to_numpy(std::move(vertex_map), {m}),
                        to_numpy(signed_indices(report.face_source), {f}),
                        to_numpy(signed_indices(report.corner_source), {f, 3}),
                        report_dict(report, opt.max_error > 0, seconds, diagonal));
}

} // namespace

void register_tiled(nb::module_& m); // tiled_module.cpp
void register_lods(nb::module_& m);  // lods_module.cpp

NB_MODULE(_core, m) {
  m.doc() = "vrsimplify's C++ core (use vrsimplify.simplify)";
  m.attr("__version__") = VRS_VERSION;
  m.def("simplify", &simplify, nb::arg("vertices"), nb::arg("faces"), nb::arg("target_kind"),
        nb::arg("target_value"), nb::arg("max_error"), nb::arg("mode"), nb::arg("threads"),
        nb::arg("simplify_boundary"), nb::arg("keep_boundary"), nb::arg("max_jump"),
        nb::arg("feature_angle"), nb::arg("seams").none(), nb::arg("locked").none(),
        nb::arg("progress").none(), nb::arg("split_vertices") = "seam",
        nb::arg("polygon_faces").none() = nb::none());
  // The MeshLab filter hands pymeshlab its stop reason as a number (strings do not pass).
  m.def("stop_reason_name", [](int code) -> std::string {
    if (code < 0 || code > int(vrs::StopReason::ErrorBound))
      throw nb::value_error("unknown stop reason");
    return vrs::stop_reason_name(vrs::StopReason(code));
  });
  register_tiled(m);
  register_lods(m);
  m.def("bounding_box_diagonal", [](AnyArray vertices) {
    vrs::Mesh mesh;
    mesh.positions = read_positions(vertices);
    return vrs::bounding_box_diagonal(mesh);
  });
}
