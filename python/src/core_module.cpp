// vrsimplify._core: the C++ core behind the numpy API (python/vrsimplify/__init__.py holds the
// Python side: argument checks a user reads, the targets, the result type). Arrays are read
// through their strides straight into the core's mesh (the one copy an in-place core needs,
// which also leaves the caller's arrays untouched). The run goes on a thread of its own while
// the caller waits with the GIL released and looks for Ctrl-C every few tens of milliseconds:
// Python handles signals on its main thread only, and the core looks at its progress hook
// only between steps (the set-up of a million faces takes seconds). The progress callback is
// served from that hook, which takes the GIL back briefly.
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
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

// Runs abandoned to Ctrl-C that have not stopped yet: Python waits for them at exit, before
// it finalizes (they touch no Python object once abandoned; they stop at their next step).
std::mutex abandoned_mutex;
std::condition_variable abandoned_done;
int abandoned_runs = 0;

// One run and everything it reads, shared by the caller and the run's thread: an abandoned run
// finishes on its own, on its own copy of the mesh.
struct Run {
  vrs::Mesh mesh;
  vrs::Options opt;
  std::vector<uint32_t> seam_pairs;
  std::vector<uint8_t> lock, polygon; // the triangles of polygons the caller puts back whole
  vrs::Report report;
  // Read and written with the GIL held only; emptied (never destroyed later) once abandoned.
  nb::object progress;
  std::optional<nb::python_error> error; // raised by the callback
  std::atomic<bool> abandoned{false};
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
};

// The core's run of `run` on a thread of its own, the caller waiting (GIL released) and
// looking for signals every 20 ms: a KeyboardInterrupt leaves the run to stop by itself.
void run_interruptible(const std::shared_ptr<Run>& run) {
  std::thread worker([run] {
    run->report = vrs::simplify(run->mesh, run->opt);
    bool abandoned;
    {
      std::lock_guard<std::mutex> lock(run->mutex);
      run->done = true;
      abandoned = run->abandoned.load();
    }
    run->finished.notify_all();
    if (abandoned) {
      std::lock_guard<std::mutex> lock(abandoned_mutex);
      if (--abandoned_runs == 0) abandoned_done.notify_all();
    }
  });
  for (;;) {
    {
      nb::gil_scoped_release release;
      std::unique_lock<std::mutex> lock(run->mutex);
      if (run->finished.wait_for(lock, std::chrono::milliseconds(20), [&] { return run->done; }))
        break;
    }
    if (PyErr_CheckSignals() != 0) { // KeyboardInterrupt (or a signal handler's exception)
      {
        std::lock_guard<std::mutex> lock(run->mutex);
        if (!run->done) {
          std::lock_guard<std::mutex> count(abandoned_mutex);
          ++abandoned_runs;
          run->abandoned.store(true);
        }
      }
      run->progress = nb::object(); // under the GIL: the run's thread never touches it again
      run->error.reset();
      worker.detach();
      throw nb::python_error();
    }
  }
  worker.join();
}

nb::tuple simplify(AnyArray vertices, AnyArray faces, const std::string& target_kind,
                   double target_value, double max_error, const std::string& mode, int threads,
                   bool simplify_boundary, bool keep_boundary, double max_jump,
                   double feature_angle, std::optional<AnyArray> seams,
                   std::optional<AnyArray> locked, nb::object progress,
                   const std::string& split_vertices, std::optional<AnyArray> polygon_faces) {
  auto run = std::make_shared<Run>();
  vrs::Options& opt = run->opt;
  opt = make_options({target_kind, target_value}, max_error, mode, threads, simplify_boundary,
                     keep_boundary, max_jump, feature_angle);
  if (split_vertices == "seam")
    opt.split_vertices = vrs::SplitVertices::Seam;
  else if (split_vertices == "weld")
    opt.split_vertices = vrs::SplitVertices::Weld;
  else if (split_vertices == "keep")
    opt.split_vertices = vrs::SplitVertices::Keep;
  else
    throw nb::value_error("split_vertices must be seam, weld or keep");
  vrs::Mesh& mesh = run->mesh;
  mesh.positions = read_positions(vertices);
  const size_t n = mesh.vertex_count();
  mesh.triangles = read_indices(faces, n, "mesh_faces", 3);
  if (seams) {
    run->seam_pairs = read_indices(*seams, n, "seams", 2);
    opt.constrained_edges = &run->seam_pairs;
  }
  if (locked) {
    run->lock = read_mask(*locked, n, "locked", "vertex");
    opt.locked = &run->lock;
  }
  if (polygon_faces) {
    run->polygon = read_mask(*polygon_faces, mesh.face_count(), "polygon_faces", "face");
    opt.polygon_faces = &run->polygon;
  }

  // Served every few hundred removals on the run's thread, the GIL taken only here: other
  // Python threads run meanwhile, and so may another simplification.
  const bool has_progress = !progress.is_none();
  run->progress = std::move(progress);
  Run* r = run.get(); // kept alive by the run's thread
  opt.progress = [r, has_progress](float fraction) -> bool {
    if (r->abandoned.load()) return false;
    if (!has_progress) return true;
    nb::gil_scoped_acquire acquire;
    if (r->abandoned.load() || r->error) return false;
    try {
      // Any object Python calls true goes on (np.True_, 1, a non-empty string): as `if`.
      // None goes on too: a callback that only prints returns nothing.
      nb::object go_on = r->progress(fraction);
      if (go_on.is_none()) return true;
      const int truth = PyObject_IsTrue(go_on.ptr());
      if (truth < 0) throw nb::python_error();
      return truth != 0;
    } catch (nb::python_error& e) {
      r->error.emplace(std::move(e));
      return false;
    }
  };

  const double diagonal = vrs::bounding_box_diagonal(mesh);
  const auto t0 = std::chrono::steady_clock::now();
  run_interruptible(run);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (run->error) { // the callback's exception, as it was raised
    nb::python_error e = std::move(*run->error);
    run->error.reset();
    throw e;
  }
  const vrs::Report& report = run->report;
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

void register_tiled(nb::module_& m);       // tiled_module.cpp
void register_lods(nb::module_& m);        // lods_module.cpp
void register_progressive(nb::module_& m); // progressive_module.cpp

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
  // Called at exit (vrsimplify/__init__.py): runs abandoned to Ctrl-C stop before Python
  // finalizes, so that none is left holding memory Python frees.
  m.def("wait_abandoned_runs", [] {
    nb::gil_scoped_release release;
    std::unique_lock<std::mutex> lock(abandoned_mutex);
    abandoned_done.wait(lock, [] { return abandoned_runs == 0; });
  });
  register_tiled(m);
  register_lods(m);
  register_progressive(m);
  m.def("bounding_box_diagonal", [](AnyArray vertices) {
    vrs::Mesh mesh;
    mesh.positions = read_positions(vertices);
    return vrs::bounding_box_diagonal(mesh);
  });
}
