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

#include "vrs/simplify.h"

namespace nb = nanobind;

namespace {

using AnyArray = nb::ndarray<nb::ro, nb::device::cpu>;

template <class T> const T* element(const AnyArray& a, size_t i, size_t j) {
  const T* base = static_cast<const T*>(a.data());
  return base + int64_t(i) * a.stride(0) + int64_t(j) * a.stride(1);
}

void check_rows(const AnyArray& a, const char* what, size_t columns) {
  if (a.ndim() != 2 || a.shape(1) != columns)
    throw nb::value_error(
        (std::string(what) + " must be an (n, " + std::to_string(columns) + ") array").c_str());
}

std::vector<float> read_positions(const AnyArray& a) {
  check_rows(a, "vertices", 3);
  std::vector<float> out(3 * a.shape(0));
  const bool f32 = a.dtype() == nb::dtype<float>();
  if (!f32 && a.dtype() != nb::dtype<double>())
    throw nb::value_error("vertices must be float32 or float64");
  for (size_t i = 0; i < a.shape(0); ++i)
    for (size_t j = 0; j < 3; ++j)
      out[3 * i + j] = f32 ? *element<float>(a, i, j) : float(*element<double>(a, i, j));
  return out;
}

template <class T>
void read_indices_as(const AnyArray& a, size_t bound, const char* what,
                     std::vector<uint32_t>& out) {
  const size_t columns = a.shape(1);
  for (size_t i = 0; i < a.shape(0); ++i)
    for (size_t j = 0; j < columns; ++j) {
      const T v = *element<T>(a, i, j);
      // Checked here, not by the core: a negative or 64-bit index must not wrap into range.
      if (v < T(0) || uint64_t(v) >= bound)
        throw nb::value_error((std::string(what) + " " + std::to_string(i) + " has vertex index " +
                               std::to_string(v) + ", out of range for " + std::to_string(bound) +
                               " vertices")
                                  .c_str());
      out[columns * i + j] = uint32_t(v);
    }
}

std::vector<uint32_t> read_indices(const AnyArray& a, size_t bound, const char* what,
                                   size_t columns) {
  check_rows(a, what, columns);
  std::vector<uint32_t> out(columns * a.shape(0));
  const nb::dlpack::dtype t = a.dtype();
  if (t == nb::dtype<int32_t>())
    read_indices_as<int32_t>(a, bound, what, out);
  else if (t == nb::dtype<int64_t>())
    read_indices_as<int64_t>(a, bound, what, out);
  else if (t == nb::dtype<uint32_t>())
    read_indices_as<uint32_t>(a, bound, what, out);
  else if (t == nb::dtype<uint64_t>())
    read_indices_as<uint64_t>(a, bound, what, out);
  else
    throw nb::value_error((std::string(what) + " must hold integers").c_str());
  return out;
}

template <class T>
nb::ndarray<nb::numpy, T> to_numpy(std::vector<T>&& v, std::initializer_list<size_t> shape) {
  auto* owned = new std::vector<T>(std::move(v));
  nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
  return nb::ndarray<nb::numpy, T>(owned->data(), shape, owner);
}

std::vector<int64_t> signed_indices(const std::vector<uint32_t>& v) {
  std::vector<int64_t> out(v.size());
  for (size_t i = 0; i < v.size(); ++i)
    out[i] = v[i] == vrs::kRemoved ? -1 : int64_t(v[i]);
  return out;
}

// The report, with the CLI's JSON keys (docs/report.md is the table of them all).
nb::dict report_dict(const vrs::Report& r, bool bounded, double seconds, double diagonal) {
  nb::dict d, rejected, kept, input;
  d["ok"] = r.ok;
  d["stop_reason"] = vrs::stop_reason_name(r.stop);
  d["target_reached"] = r.target_reached;
  d["stop_detail"] = r.stop_detail;
  d["message"] = r.message;
  d["input_vertices"] = r.input_vertices;
  d["input_faces"] = r.input_faces;
  d["output_vertices"] = r.vertices;
  d["output_faces"] = r.faces;
  d["removed"] = r.removed;
  for (int i = 0; i < vrs::RejectCount; ++i)
    rejected[vrs::reject_name(vrs::Reject(i))] = r.rejected[i];
  d["rejected"] = rejected;
  d["rejected_total"] = r.rejected_total();
  kept["boundary"] = r.kept_boundary;
  kept["nonmanifold"] = r.kept_nonmanifold;
  kept["locked"] = r.kept_locked;
  kept["high_valence"] = r.kept_high_valence;
  kept["constrained"] = r.kept_constrained;
  d["kept"] = kept;
  d["constrained_edges"] = r.constrained_edges;
  input["degenerate_faces"] = r.dropped_degenerate_faces;
  input["nonfinite_vertices"] = r.nonfinite_vertices;
  input["unreferenced_vertices"] = r.unreferenced_vertices;
  input["reoriented_faces"] = r.reoriented_faces;
  d["input_issues"] = input;
  d["relaxed_removals"] = r.relaxed_removals;
  d["boundary_simplified"] = r.boundary_simplified;
  d["max_removed_factor"] = r.max_removed_factor;
  // Not tracked: None, never 0.0 (which would read "no error at all").
  d["error_bound"] = bounded ? nb::object(nb::float_(r.error_bound)) : nb::none();
  d["error_bound_percent"] =
      bounded ? nb::object(nb::float_(diagonal > 0 ? 100.0 * r.error_bound / diagonal : 0.0))
              : nb::none();
  d["seconds_simplify"] = seconds;
  return d;
}

struct Target {
  std::string kind; // "ratio", "faces", "vertices", "bound" (max_error alone)
  double value;
};

vrs::Options make_options(const Target& target, double max_error, const std::string& mode,
                          int threads, bool simplify_boundary, bool keep_boundary, double max_jump,
                          double feature_angle) {
  vrs::Options opt;
  if (target.kind == "ratio") {
    opt.target.kind = vrs::TargetKind::Ratio;
    opt.target.ratio = target.value;
  } else if (target.kind == "faces" || target.kind == "vertices") {
    if (!(target.value >= 0) || target.value != std::floor(target.value))
      throw nb::value_error((target.kind + " must be a count >= 0").c_str());
    const bool faces = target.kind == "faces";
    opt.target.kind = faces ? vrs::TargetKind::Faces : vrs::TargetKind::Vertices;
    (faces ? opt.target.faces : opt.target.vertices) = size_t(target.value);
  } else if (target.kind == "bound") { // max_error alone: as far as the bound allows
    opt.target.kind = vrs::TargetKind::Faces;
    opt.target.faces = 0;
    // No count to reach: the last resort, which lifts vetoes to reach one, has nothing to do.
    opt.relax_to_reach_target = false;
  } else {
    throw nb::value_error(("unknown target " + target.kind).c_str());
  }
  if (!vrs::parse_mode(mode, opt.mode))
    throw nb::value_error("mode must be surface, terrain or planar");
  opt.max_error = max_error;
  opt.threads = threads;
  opt.simplify_boundary = simplify_boundary;
  opt.simplify_boundary_when_needed = !keep_boundary;
  if (!(max_jump >= 0)) throw nb::value_error("max_jump must be >= 0 (0: the target at any cost)");
  opt.max_price_jump = max_jump;
  opt.feature_angle_deg = feature_angle;
  opt.corner_sources = true;
  return opt;
}

nb::tuple simplify(AnyArray vertices, AnyArray faces, const std::string& target_kind,
                   double target_value, double max_error, const std::string& mode, int threads,
                   bool simplify_boundary, bool keep_boundary, double max_jump,
                   double feature_angle, std::optional<AnyArray> seams,
                   std::optional<AnyArray> locked, nb::object progress) {
  vrs::Options opt = make_options({target_kind, target_value}, max_error, mode, threads,
                                  simplify_boundary, keep_boundary, max_jump, feature_angle);
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
    const AnyArray& l = *locked;
    if (l.ndim() != 1 || l.shape(0) != n || l.dtype() != nb::dtype<bool>())
      throw nb::value_error("locked must be a boolean array of one entry per vertex");
    lock.resize(n);
    const bool* base = static_cast<const bool*>(l.data());
    for (size_t i = 0; i < n; ++i)
      lock[i] = base[int64_t(i) * l.stride(0)];
    opt.locked = &lock;
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

NB_MODULE(_core, m) {
  m.doc() = "vrsimplify's C++ core (use vrsimplify.simplify)";
  m.attr("__version__") = VRS_VERSION;
  m.def("simplify", &simplify, nb::arg("vertices"), nb::arg("faces"), nb::arg("target_kind"),
        nb::arg("target_value"), nb::arg("max_error"), nb::arg("mode"), nb::arg("threads"),
        nb::arg("simplify_boundary"), nb::arg("keep_boundary"), nb::arg("max_jump"),
        nb::arg("feature_angle"), nb::arg("seams").none(), nb::arg("locked").none(),
        nb::arg("progress").none());
  // The MeshLab filter hands pymeshlab its stop reason as a number (strings do not pass).
  m.def("stop_reason_name", [](int code) -> std::string {
    if (code < 0 || code > int(vrs::StopReason::ErrorBound))
      throw nb::value_error("unknown stop reason");
    return vrs::stop_reason_name(vrs::StopReason(code));
  });
  register_tiled(m);
  m.def("bounding_box_diagonal", [](AnyArray vertices) {
    vrs::Mesh mesh;
    mesh.positions = read_positions(vertices);
    return vrs::bounding_box_diagonal(mesh);
  });
}
