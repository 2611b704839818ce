// vrsimplify._core's tiled steps (python/vrsimplify/tiled.py drives them, locally or on Dask):
// each is a function of the work directory, so any process that sees it can run a tile.
#include <cstdint>
#include <stdexcept>
#include <string>

#include <nanobind/nanobind.h>
#include <nanobind/stl/string.h>

#include "vrs/tiled.h"

namespace nb = nanobind;

namespace {

nb::dict level_dict(const vrs::tiled::Level& l) {
  nb::dict d;
  d["level"] = l.level;
  d["tiles"] = l.tiles;
  d["faces"] = l.faces;
  d["target"] = l.target;
  d["ratio"] = l.ratio;
  d["serial"] = l.serial;
  return d;
}

vrs::tiled::Level level_of(const nb::dict& d) {
  vrs::tiled::Level l;
  l.level = nb::cast<int>(d["level"]);
  l.tiles = nb::cast<uint64_t>(d["tiles"]);
  l.faces = nb::cast<uint64_t>(d["faces"]);
  l.target = nb::cast<uint64_t>(d["target"]);
  l.ratio = nb::cast<double>(d["ratio"]);
  l.serial = d.contains("serial") && nb::cast<bool>(d["serial"]);
  return l;
}

// Our errors are the user's (a bad file, a full disk): ValueError for input, OSError else.
template <class F> auto guarded(F&& f) {
  try {
    nb::gil_scoped_release release;
    return f();
  } catch (const std::runtime_error& e) {
    throw nb::value_error(e.what());
  }
}

} // namespace

void register_tiled(nb::module_& m) {
  m.def(
      "tiled_begin",
      [](const std::string& input, const std::string& workdir, double ratio,
         uint64_t faces_per_tile, const std::string& split_vertices) {
        vrs::tiled::Settings s;
        s.ratio = ratio;
        s.faces_per_tile = faces_per_tile;
        s.workdir = workdir;
        s.split_vertices = split_vertices;
        return level_dict(guarded([&] { return vrs::tiled::begin(input, s); }));
      },
      nb::arg("input"), nb::arg("workdir"), nb::arg("ratio"), nb::arg("faces_per_tile"),
      nb::arg("split_vertices") = "");
  m.def("tiled_run_tile", [](const std::string& workdir, int level, uint64_t tile) {
    guarded([&] {
      vrs::tiled::run_tile(workdir, level, tile);
      return 0;
    });
  });
  m.def("tiled_run_level_locally",
        [](const std::string& workdir, const nb::dict& level, int workers, bool progress) {
          const vrs::tiled::Level l = level_of(level);
          guarded([&] {
            // Ctrl-C: KeyboardInterrupt, once the workers are gone (Python's handler only
            // notes the signal; it is run here).
            vrs::tiled::run_level_locally(workdir, l, workers, progress, [] {
              nb::gil_scoped_acquire acquire;
              if (PyErr_CheckSignals() != 0) throw nb::python_error();
            });
            return 0;
          });
        });
  m.def("tiled_next_level", [](const std::string& workdir) {
    return level_dict(guarded([&] { return vrs::tiled::next_level(workdir); }));
  });
  m.def("tiled_finish", [](const std::string& workdir, const std::string& output) {
    return guarded([&] { return vrs::tiled::finish(workdir, output); });
  });
  m.def("tiled_make_work_dir", [](const std::string& parent) {
    return guarded([&] { return vrs::tiled::make_work_dir(parent); });
  });
  m.def("tiled_discard", [](const std::string& workdir) { vrs::tiled::discard(workdir); });
  m.def("tiled_faces_for_memory", &vrs::tiled::faces_for_memory);
  m.def("tiled_output_refusal", &vrs::tiled::output_refusal);
  m.def("tiled_fits_in_core", &vrs::tiled::fits_in_core);
  m.def("tiled_parse_memory", &vrs::tiled::parse_memory);
  m.attr("tiles_in_memory") = vrs::tiled::kTilesInMemory;
}
