// vrs_bench: every method on the same mesh and targets, one CSV line per run.
//   vrs_bench MESH [--name N] [--ratios 0.5,0.1,0.01] [--methods ours,qecd,meshopt,vtk]
//             [--samples S] [--header] [--save DIR]
//   vrs_bench --compare A B [--samples S]   B against A: "max mean rms fold_area"
//   vrs_bench --info MESH                      "faces open" (open: 1 when it has a border)
//   vrs_bench --bound MESH E,.. [--samples S] [--name N]
//             ours, meshoptimizer and vtkDecimatePro with an error limit E (fraction of the
//             bounding-box diagonal) and no face target: faces reached, measured error, and
//             our certified bound (rows: mesh,input_faces,bound,method,output_faces,seconds,
//             error_max,error_mean,certified)
//   vrs_bench --serial MESH RATIO [THREADS [PART_VERTICES]]
//             our default run (or with parts of PART_VERTICES vertices) instrumented: "seconds
//             parallel_seconds serial_fraction by_chunks_8 by_chunks_16" (the time in loops
//             spread over the threads, the rest, and on one thread the speed-up its loops'
//             chunks allow on 8 and 16)
//   vrs_bench --loop MESH LEVELS OUT.ply       Loop subdivision (large inputs)
//   vrs_bench --terrain K OUT.ply              (2^K + 1)^2 fractal terrain
//   vrs_bench --streamed-terrain N OUT.ply     N^2 terrain written a row at a time (any size)
//   vrs_bench --convert MESH OUT.ply           the mesh as every method here reads it (binary
//                                             PLY: what bench/python_peers.py hands to Python)
// Methods: ours (defaults) with suffixes -factor / -local (priority), -linear / -log (mapping),
// -heap (exact queue), -eager (every neighbour re-priced at once), -tN (N threads;
// default 1 here, so that runs compare), -intN (N intervals), -projection (the paper's filling
// only), -boundary (boundary simplified), combinable; qecd, qecd-topology (Preserve Topology on),
// qecd-keep (QECD with optimal placement off: a half-edge collapse, output vertices are input
// vertices), qecd-at-M (QECD to the face count method M ends with, e.g. qecd-at-ours,
// qecd-at-openmesh: equal size where M stops short), openmesh (OpenMesh decimater + quadric
// module), meshopt, vtk. Each run is a child process, so memory high-water marks do not carry over
// from one run to the next.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "make_inputs.h"
#include "mesh_io.h"
#include "peers.h"
#include "surface_error.h"

namespace {

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

bool run_method(const std::string& method, const vrs::Mesh& in, size_t target,
                vrs_bench::PeerResult& r) {
  using namespace vrs_bench;
  if (method == "qecd")
    r = run_qecd(in, target);
  else if (method == "qecd-topology")
    r = run_qecd(in, target, /*preserve_topology=*/true);
  else if (method == "qecd-keep")
    r = run_qecd(in, target, /*preserve_topology=*/false, /*optimal_placement=*/false);
  else if (method.rfind("qecd-at-", 0) == 0) {
    // QECD at the face count another method ends with (qecd-at-ours, qecd-at-openmesh, ...):
    // where that method stops short of the target, what MeshLab's filter does with as many
    // faces (the comparison at equal size).
    PeerResult other;
    if (!run_method(method.substr(8), in, target, other)) return false;
    r = run_qecd(in, other.mesh.face_count());
  } else if (method == "openmesh")
    r = run_openmesh(in, target);
  else if (method == "meshopt")
    r = run_meshopt(in, target);
  else if (method == "vtk")
    r = run_vtk(in, target);
  else if (method.rfind("ours", 0) == 0) {
    // "ours" then any of -factor|-local, -linear|-log, -heap, -whole, -intN, e.g. ours-local-heap.
    vrs::Options o;
    o.threads = 1; // one thread unless -tN: the peers run on one
    // The benchmark's meshes are positions only: split copies are interchangeable, as the
    // command-line tool judges them (-seam / -keep: the other ways).
    o.split_vertices = vrs::SplitVertices::Weld;
    std::stringstream parts(method.substr(4));
    std::string p;
    while (std::getline(parts, p, '-')) {
      if (p.empty()) continue;
      if (p == "factor")
        o.tuning.priority = vrs::Priority::Factor;
      else if (p == "local")
        o.tuning.priority = vrs::Priority::LocalError;
      else if (p == "linear")
        o.tuning.mapping = vrs::IntervalMapping::Linear;
      else if (p == "log")
        o.tuning.mapping = vrs::IntervalMapping::Logarithmic;
      else if (p == "projection")
        o.tuning.fill = vrs::Fill::Projection;
      else if (p == "boundary")
        o.simplify_boundary = true;
      else if (p.size() > 1 && p[0] == 't' && std::isdigit(static_cast<unsigned char>(p[1])))
        o.threads = std::atoi(p.c_str() + 1);
      else if (p == "eager")
        o.tuning.lazy_reevaluation = false;
      else if (p == "lazy") // lazy whatever the size (the default is eager on small meshes)
        o.tuning.lazy_from_faces = 0;
      else if (p == "bound") // track the certified error bound, no limit
        o.max_error = std::numeric_limits<double>::infinity();
      else if (p.rfind("fa", 0) == 0 && p.size() > 2 &&
               std::isdigit(static_cast<unsigned char>(p[2])))
        o.feature_angle_deg = std::atof(p.c_str() + 2); // crease angle, e.g. ours-fa70
      else if (p == "norelax")                          // stop short instead of the last resort
        o.relax_to_reach_target = false;
      else if (p == "input")
        o.tuning.against_input = true;
      else if (p == "noinput")
        o.tuning.against_input = false;
      else if (p == "heap")
        o.tuning.queue = vrs::QueueKind::Heap;
      else if (p == "noslide") // the run's faces, no slide after it
        o.slide = false;
      else if (p == "seam")
        o.split_vertices = vrs::SplitVertices::Seam;
      else if (p == "keep")
        o.split_vertices = vrs::SplitVertices::Keep;
      else if (p == "whole") // one queue from the start, no parts
        o.tuning.part_vertices = 0;
      else if (p.rfind("part", 0) == 0 && p.size() > 4) // e.g. ours-part1024
        o.tuning.part_vertices = std::atoi(p.c_str() + 4);
      else if (p.rfind("jump", 0) == 0 && p.size() > 4) // e.g. ours-jump0: the target at any cost
        o.max_price_jump = std::atof(p.c_str() + 4);
      else if (p.rfind("int", 0) == 0 && p.size() > 3)
        o.tuning.intervals = std::atoi(p.c_str() + 3);
      else
        return false;
    }
    r = run_ours(in, target, o);
  } else {
    return false;
  }
  return true;
}

bool load_core(const std::string& path, vrs::Mesh& out) {
  vrs_tool::LoadResult loaded = vrs_tool::load(path);
  if (!loaded.doc) {
    std::fprintf(stderr, "vrs_bench: %s\n", loaded.error.c_str());
    return false;
  }
  out = vrs_tool::to_core(*loaded.doc);
  vrs_tool::close(loaded.doc);
  return true;
}

int compare(int argc, char** argv) {
  if (argc < 4) return 2;
  size_t samples = 200000;
  if (argc >= 6 && std::string(argv[4]) == "--samples")
    samples = std::strtoull(argv[5], nullptr, 10);
  vrs::Mesh a, b;
  if (!load_core(argv[2], a) || !load_core(argv[3], b)) return 1;
  vrs_bench::SurfaceError e = vrs_bench::surface_error(a, b, samples);
  std::printf("%.6g %.6g %.6g %.6g\n", e.max, e.mean, e.rms,
              vrs_bench::fold_over_share(a, b, samples));
  return 0;
}

// "faces open": the face count, and 1 when some edge has a single face (the mesh has a border).
int info(int argc, char** argv) {
  if (argc < 3) return 2;
  vrs::Mesh m;
  if (!load_core(argv[2], m) || m.face_count() == 0) return 1;
  std::vector<uint64_t> edges;
  const auto& t = m.triangles;
  for (size_t i = 0; i < t.size(); i += 3)
    for (int c = 0; c < 3; ++c) {
      uint64_t a = t[i + c], b = t[i + (c + 1) % 3];
      edges.push_back(std::min(a, b) << 32 | std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  bool open = false;
  for (size_t i = 0; i < edges.size() && !open;) {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i])
      ++j;
    open = j - i == 1;
    i = j;
  }
  std::printf("%zu %d\n", m.face_count(), open ? 1 : 0);
  return 0;
}

int bound(int argc, char** argv) {
  if (argc < 4) return 2;
  const std::string path = argv[2];
  std::vector<std::string> bounds = split(argv[3]);
  size_t samples = 200000;
  std::string name = path.substr(path.find_last_of('/') + 1);
  name = name.substr(0, name.find('.'));
  for (int i = 4; i + 1 < argc; i += 2) {
    if (std::string(argv[i]) == "--samples") samples = std::strtoull(argv[i + 1], nullptr, 10);
    if (std::string(argv[i]) == "--name") name = argv[i + 1];
  }
  vrs::Mesh in;
  if (!load_core(path, in)) return 1;
  const double diag = vrs::bounding_box_diagonal(in) > 0 ? vrs::bounding_box_diagonal(in) : 1.0;
  int failures = 0;
  for (const std::string& b : bounds) {
    const double e = std::atof(b.c_str()) * diag;
    for (const char* method : {"ours", "meshopt", "vtk"}) {
      std::fflush(stdout);
      pid_t pid = fork();
      if (pid == 0) {
        vrs::Options o;
        o.threads = 1;
        o.split_vertices = vrs::SplitVertices::Weld; // positions only, as "ours"
        const std::string m = method;
        vrs_bench::PeerResult r = m == "ours"      ? vrs_bench::run_ours_bound(in, e, o)
                                  : m == "meshopt" ? vrs_bench::run_meshopt_bound(in, e)
                                                   : vrs_bench::run_vtk_bound(in, e);
        vrs_bench::SurfaceError s = vrs_bench::surface_error(in, r.mesh, samples);
        std::printf("%s,%zu,%s,%s,%zu,%.6f,%.6g,%.6g,", name.c_str(), in.face_count(), b.c_str(),
                    method, r.mesh.face_count(), r.seconds, s.max, s.mean);
        if (m == "ours") std::printf("%.6g", r.error_bound / diag);
        std::printf("\n");
        std::fflush(stdout);
        _exit(0);
      }
      int status = 0;
      waitpid(pid, &status, 0);
      failures += !WIFEXITED(status) || WEXITSTATUS(status) != 0;
    }
  }
  return failures ? 1 : 0;
}

// Amdahl's serial fraction as the run itself measures it: the time outside the loops spread
// over the threads, over the whole run (on one thread: what no thread count shortens).
int serial(int argc, char** argv) {
  if (argc < 4) return 2;
  vrs::Mesh m;
  if (!load_core(argv[2], m)) return 1;
  vrs::Options o;
  o.target.ratio = std::atof(argv[3]);
  o.threads = argc > 4 ? std::atoi(argv[4]) : 1;
  if (argc > 5) o.tuning.part_vertices = std::atoi(argv[5]); // another part size than the default
  double seconds_8 = 0, seconds_16 = 0;
  const vrs::Report r = vrs_bench::run_ours_projected(m, o, seconds_8, seconds_16);
  if (!r.ok) {
    std::fprintf(stderr, "vrs_bench: %s\n", r.message.c_str());
    return 1;
  }
  std::printf("%.4f %.4f %.4f %.2f %.2f\n", r.seconds, r.parallel_seconds,
              1.0 - r.parallel_seconds / r.seconds, r.seconds / seconds_8, r.seconds / seconds_16);
  return 0;
}

int make(int argc, char** argv) {
  vrs::Mesh m;
  std::string out;
  if (std::string(argv[1]) == "--loop" && argc == 5) {
    vrs::Mesh in;
    if (!load_core(argv[2], in)) return 1;
    m = vrs_bench::loop_subdivide(in, std::atoi(argv[3]));
    out = argv[4];
  } else if (std::string(argv[1]) == "--convert" && argc == 4) {
    if (!load_core(argv[2], m)) return 1;
    out = argv[3];
  } else if (std::string(argv[1]) == "--streamed-terrain" && argc == 4) {
    const std::string err =
        vrs_bench::write_streamed_terrain(uint32_t(std::atol(argv[2])), argv[3]);
    if (!err.empty()) std::fprintf(stderr, "vrs_bench: %s\n", err.c_str());
    return err.empty() ? 0 : 1;
  } else if (std::string(argv[1]) == "--terrain" && argc == 4) {
    m = vrs_bench::fractal_terrain(std::atoi(argv[2]), 2026);
    out = argv[3];
  } else {
    return 2;
  }
  std::string err = vrs_bench::write_ply(m, out);
  if (!err.empty()) {
    std::fprintf(stderr, "vrs_bench: %s\n", err.c_str());
    return 1;
  }
  std::printf("%s: %zu vertices, %zu faces\n", out.c_str(), m.vertex_count(), m.face_count());
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: vrs_bench MESH [--name N] [--ratios R,..] [--methods M,..] "
                         "[--samples S] [--header] [--save DIR]\n");
    return 2;
  }
  if (std::string(argv[1]) == "--compare") return compare(argc, argv);
  if (std::string(argv[1]) == "--info") return info(argc, argv);
  if (std::string(argv[1]) == "--bound") return bound(argc, argv);
  if (std::string(argv[1]) == "--serial") return serial(argc, argv);
  if (std::string(argv[1]) == "--loop" || std::string(argv[1]) == "--terrain" ||
      std::string(argv[1]) == "--streamed-terrain" || std::string(argv[1]) == "--convert")
    return make(argc, argv);
  std::string path = argv[1], name;
  std::vector<std::string> ratios = {"0.5", "0.1", "0.01"},
                           methods = {"ours", "qecd", "meshopt", "vtk"};
  size_t samples = 200000;
  bool header = false;
  std::string save_dir; // where to write each run's output mesh (for the report's renders)
  for (int i = 2; i < argc; ++i) {
    std::string a = argv[i];
    auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (a == "--name")
      name = next();
    else if (a == "--ratios")
      ratios = split(next());
    else if (a == "--methods")
      methods = split(next());
    else if (a == "--samples")
      samples = std::strtoull(next().c_str(), nullptr, 10);
    else if (a == "--header")
      header = true;
    else if (a == "--save")
      save_dir = next();
    else {
      std::fprintf(stderr, "vrs_bench: unknown option %s\n", a.c_str());
      return 2;
    }
  }
  if (name.empty()) {
    name = path.substr(path.find_last_of('/') + 1);
    name = name.substr(0, name.find('.'));
  }
  vrs::Mesh in;
  if (!load_core(path, in)) return 1;

  if (header)
    std::printf("mesh,input_faces,ratio,target_faces,method,output_faces,output_vertices,seconds,"
                "peak_mb,extra_mb,error_max,error_mean,error_rms,fold_area,note\n");
  std::fflush(stdout);
  int failures = 0;
  for (const std::string& ratio : ratios) {
    const size_t target = size_t(std::atof(ratio.c_str()) * double(in.face_count()) + 0.5);
    for (const std::string& method : methods) {
      pid_t pid = fork();
      if (pid == 0) {
        vrs_bench::PeerResult r;
        if (!run_method(method, in, target, r)) {
          std::fprintf(stderr, "vrs_bench: unknown method %s\n", method.c_str());
          _exit(2);
        }
        if (!save_dir.empty())
          vrs_bench::write_ply(r.mesh, save_dir + "/" + name + "_" + ratio + "_" + method + ".ply");
        vrs_bench::SurfaceError e = vrs_bench::surface_error(in, r.mesh, samples);
        double folds = vrs_bench::fold_over_share(in, r.mesh, samples);
        if (r.error_bound > 0) // the certified bound, relative to the diagonal as the errors
          r.note += (r.note.empty() ? "" : " ") + std::string("bound=") +
                    std::to_string(r.error_bound / (e.diagonal > 0 ? e.diagonal : 1.0));
        std::printf("%s,%zu,%s,%zu,%s,%zu,%zu,%.6f,%.1f,%.1f,%.6g,%.6g,%.6g,%.6g,%s\n",
                    name.c_str(), in.face_count(), ratio.c_str(), target, method.c_str(),
                    r.mesh.face_count(), r.mesh.vertex_count(), r.seconds, r.peak_mb, r.extra_mb,
                    e.max, e.mean, e.rms, folds, r.note.c_str());
        std::fflush(stdout);
        _exit(0);
      }
      int status = 0;
      waitpid(pid, &status, 0);
      if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::fprintf(stderr, "vrs_bench: %s on %s at %s failed (status %d)\n", method.c_str(),
                     name.c_str(), ratio.c_str(), status);
        // The row stays in the table: a peer that crashes on an input is a result too.
        std::printf("%s,%zu,%s,%zu,%s,,,,,,,,,,failed (%s %d)\n", name.c_str(), in.face_count(),
                    ratio.c_str(), target, method.c_str(), WIFSIGNALED(status) ? "signal" : "exit",
                    WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
        std::fflush(stdout);
        ++failures;
      }
    }
  }
  return failures ? 1 : 0;
}
