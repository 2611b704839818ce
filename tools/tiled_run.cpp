#include "tiled_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include "interrupt_guard.h"
#include "python_module.h"
#include "vrs/simplify.h"
#include "vrs/tiled.h"

namespace vrs_tool {

uint64_t estimate_faces(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return 0;
  char line[512];
  uint64_t faces = 0;
  bool ply = std::fgets(line, sizeof line, f) && std::strncmp(line, "ply", 3) == 0;
  while (ply && std::fgets(line, sizeof line, f) && std::strncmp(line, "end_header", 10) != 0) {
    unsigned long long n;
    if (std::sscanf(line, "element face %llu", &n) == 1) faces = n;
  }
  std::fclose(f);
  struct stat st;
  if (!ply && stat(path.c_str(), &st) == 0) faces = uint64_t(st.st_size) / 30; // OBJ, ascii
  return faces;
}

namespace {

// The Dask driver lives in the Python package.
int run_on_dask(const TiledRequest& r) {
  std::vector<std::string> args = {r.input,       r.output,   "--ratio", std::to_string(r.ratio),
                                   "--scheduler", r.scheduler};
  if (r.memory) args.insert(args.end(), {"--memory", std::to_string(r.memory)});
  if (!r.workdir.empty()) args.insert(args.end(), {"--work-dir", r.workdir});
  if (!r.split_vertices.empty()) args.insert(args.end(), {"--split-vertices", r.split_vertices});
  return exec_python_module("vrsimplify.tiled", args, "--scheduler",
                            "pip install vrsimplify dask distributed");
}

int run_in(const std::string& dir, const TiledRequest& r, int workers);

} // namespace

int run_tiled(const TiledRequest& r) {
  if (!r.scheduler.empty()) return run_on_dask(r);
  const int workers =
      std::min(vrs::tiled::kTilesInMemory, r.workers > 0 ? r.workers : vrs::usable_cores());
  std::string dir;
  try {
    // Beside the output unless told: the tile files take about twice the input's size.
    const size_t slash = r.output.rfind('/');
    dir = vrs::tiled::make_work_dir(!r.workdir.empty()           ? r.workdir
                                    : slash == std::string::npos ? std::string(".")
                                                                 : r.output.substr(0, slash + 1));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vrsimplify: %s\n", e.what());
    return 1;
  }
  // Interrupted or killed, a run leaves nothing behind: its work directory (about twice the
  // input's size) and a partial output go with it, removed by a parent that outlives it.
  return run_guarded([&] { return run_in(dir, r, workers); },
                     [&](pid_t child, int sig) {
                       if (!r.keep_workdir) vrs::tiled::discard(dir);
                       std::remove(vrs::tiled::unfinished_name(r.output, child).c_str());
                       std::fprintf(stderr, "vrsimplify: stopped (%s); %s %s\n",
                                    sig ? strsignal(sig) : "lost",
                                    r.keep_workdir ? "kept" : "removed", dir.c_str());
                     });
}

namespace {

int run_in(const std::string& dir, const TiledRequest& r, int workers) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  vrs::tiled::Settings s;
  s.ratio = r.ratio;
  s.faces_per_tile = vrs::tiled::faces_for_memory(r.memory);
  s.split_vertices = r.split_vertices;
  s.workdir = dir;
  int levels = 0;
  uint64_t input_faces = 0, output_faces = 0;
  // With --progress, each step's time: what runs in one process (reading, cutting, writing)
  // against what the workers share.
  auto lap = [&, t = t0](const char* step) mutable {
    const auto now = clock::now();
    if (r.progress)
      std::fprintf(stderr, "  %s: %.2f s\n", step, std::chrono::duration<double>(now - t).count());
    t = now;
  };
  try {
    vrs::tiled::Level level = vrs::tiled::begin(r.input, s);
    lap("read and cut into tiles");
    input_faces = level.faces;
    while (level.tiles > 0) {
      vrs::tiled::run_level_locally(dir, level, workers, r.progress);
      lap("tiles simplified");
      ++levels;
      level = vrs::tiled::next_level(dir);
      lap(level.tiles > 0 ? "cut into tiles" : "checked");
    }
    output_faces = vrs::tiled::finish(dir, r.output);
    lap("written");
  } catch (const std::exception& e) {
    if (!r.keep_workdir) vrs::tiled::discard(dir);
    std::fprintf(stderr, "vrsimplify: %s\n", e.what());
    return 1;
  }
  if (!r.keep_workdir) vrs::tiled::discard(dir);
  const double seconds = std::chrono::duration<double>(clock::now() - t0).count();
  // The target as the core rounds it, and the in-core report's keys for whether it was met.
  const uint64_t target = uint64_t(std::llround(r.ratio * double(input_faces)));
  const bool reached = output_faces <= target;
  if (r.json)
    std::printf("{\"ok\":true,\"tiled\":true,\"input_faces\":%llu,\"output_faces\":%llu,"
                "\"target_faces\":%llu,\"stop_reason\":\"%s\",\"target_reached\":%s,"
                "\"levels\":%d,\"workers\":%d,\"faces_per_tile\":%llu,\"seconds_total\":%.6f}\n",
                (unsigned long long)input_faces, (unsigned long long)output_faces,
                (unsigned long long)target, reached ? "target_reached" : "no_candidates",
                reached ? "true" : "false", levels, workers, (unsigned long long)s.faces_per_tile,
                seconds);
  else {
    // Tiles stop within half a per cent of the target when what is left is still too large
    // to run in one piece (tiled.cpp): say how close, not only that it was missed.
    char missed[96] = "";
    if (!reached)
      std::snprintf(missed, sizeof missed,
                    output_faces <= target + target / 200 + 2
                        ? ", NOT reached: %.2f %% over, as near as tiles go within the budget"
                        : ", NOT reached: %.2f %% over",
                    target ? 100.0 * double(output_faces - target) / double(target) : 100.0);
    std::printf("tiled:   %llu -> %llu faces (target %llu%s) in %d levels on %d processes, "
                "tiles of up to %llu faces, %.3f s\n",
                (unsigned long long)input_faces, (unsigned long long)output_faces,
                (unsigned long long)target, missed, levels, workers,
                (unsigned long long)s.faces_per_tile, seconds);
  }
  return 0;
}

} // namespace

} // namespace vrs_tool
