// vrs_sweep: simplifies real files at several ratios and checks every invariant of each run
// (tests/support/mesh_checks.h: check_run) plus determinism (two runs, identical bits).
//   vrs_sweep [--ratios 0.5,0.1,0.01] [--priority local-error|factor] [--cancel-at F]
//             [--no-rerun] [--progress] FILE...
// PLY, OFF, OBJ and STL are read by the CLI's own readers (the code users run); every other
// format assimp knows is read by assimp (Debian libassimp-dev), all meshes of the scene joined.
// `LOADED file V F` once read, then one line per run: `RUN file ratio in_faces out_faces stop
// seconds ok|FAIL: why`; files that are not meshes or cannot be read get one `SKIP file why`
// line (the reader's verdict, not ours). Exit 1 if any run broke an invariant. --no-rerun
// skips the second run (the sanitizer build's sweep: memory errors and the invariants; the
// Release build's sweep checks determinism, and the second run was half the sanitizers' time).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "mesh_checks.h"
#include "sweep_reader.h"

namespace {

struct Args {
  std::vector<double> ratios{0.5, 0.1, 0.01};
  vrs::Priority priority = vrs::Priority::LocalError;
  double cancel_at = -1; // progress fraction at which the callback says stop
  bool progress = false;
  bool rerun = true;
  std::vector<std::string> files;
};

bool parse(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    std::string s = argv[i];
    auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
    const char* v = nullptr;
    if (s == "--ratios" && (v = value())) {
      a.ratios.clear();
      std::stringstream in(v);
      std::string r;
      while (std::getline(in, r, ','))
        a.ratios.push_back(std::atof(r.c_str()));
    } else if (s == "--priority" && (v = value())) {
      if (!vrs::parse_priority(v, a.priority)) return false;
    } else if (s == "--cancel-at" && (v = value())) {
      a.cancel_at = std::atof(v);
    } else if (s == "--no-rerun") {
      a.rerun = false;
    } else if (s == "--progress") {
      a.progress = true;
    } else if (!s.empty() && s[0] != '-') {
      a.files.push_back(s);
    } else {
      return false;
    }
  }
  return !a.files.empty() && !a.ratios.empty();
}

} // namespace

int main(int argc, char** argv) {
  Args a;
  if (!parse(argc, argv, a)) {
    std::fprintf(stderr, "usage: vrs_sweep [--ratios R,...] [--priority P] [--cancel-at F] "
                         "[--no-rerun] [--progress] FILE...\n");
    return 2;
  }
  int failed = 0;
  for (const std::string& file : a.files) {
    vrs::Mesh in;
    std::vector<uint32_t> seams;
    std::string why = vrs_sweep::read_mesh(file, in, seams);
    if (!why.empty()) {
      std::printf("SKIP %s %s\n", file.c_str(), why.c_str());
      continue;
    }
    // From here on a crash is ours, not the reader's: say so before simplifying.
    std::printf("LOADED %s %zu %zu\n", file.c_str(), in.vertex_count(), in.face_count());
    std::fflush(stdout);
    for (double ratio : a.ratios) {
      vrs::Options o;
      o.target.ratio = ratio;
      // Textured files: their seams constrained, and check_run then checks that no output
      // face spans two charts.
      o.constrained_edges = &seams;
      o.corner_sources = !seams.empty();
      o.tuning.priority = a.priority;
      float last = -1;
      if (a.progress || a.cancel_at >= 0)
        o.progress = [&](float f) {
          if (a.progress && int(f * 20) != int(last * 20))
            std::fprintf(stderr, "  %s %.2f: %3.0f %%\n", file.c_str(), ratio, 100.0 * f);
          last = f;
          return !(a.cancel_at >= 0 && f >= a.cancel_at);
        };
      vrs::Mesh out = in;
      const auto t0 = std::chrono::steady_clock::now();
      const vrs::Report rep = vrs::simplify(out, o);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::string broken = vrs_test::check_run(in, out, o, rep);
      if (broken.empty() && o.progress && last < 0) broken = "the progress callback never fired";
      if (broken.empty() && a.rerun) broken = vrs_test::check_rerun(in, o, out, rep);
      failed += !broken.empty();
      std::printf("RUN %s %.3g %zu %zu %s %.3f %s%s\n", file.c_str(), ratio, in.face_count(),
                  out.face_count(), rep.ok ? vrs::stop_reason_name(rep.stop) : "refused", seconds,
                  broken.empty() ? "ok" : "FAIL: ", broken.c_str());
      if (!rep.ok) std::printf("  message: %s\n", rep.message.c_str());
      if (rep.constrained_edges)
        std::printf("  seams: %zu constrained edges, %zu vertices kept by them\n",
                    rep.constrained_edges, rep.kept_constrained);
      std::fflush(stdout);
    }
  }
  return failed ? 1 : 0;
}
