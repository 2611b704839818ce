// vrsimplify: simplify a mesh file with the core library.
//   vrsimplify INPUT OUTPUT [target] [options]   (see usage())
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include <strings.h>
#include <unistd.h>

#include "exact_vertices.h"
#include "glb_output.h"
#include "mesh_io.h"
#include "progress_bar.h"
#include "python_module.h"
#include "tiled_run.h"
#include "vrs/simplify.h"
#include "vrs/tiled.h"

namespace {

const char* kUsage =
    "usage: vrsimplify INPUT OUTPUT [target] [options]\n"
    "       vrsimplify serve OUT.glb [--port P] [--throttle BYTES/S]   the viewer page\n"
    "  files: .ply (ascii or binary), .off, .obj, .stl; OUTPUT - writes the input's format to\n"
    "  standard output (the report then goes to standard error)\n"
    "target (one; default --ratio 0.5):\n"
    "  --ratio R          keep R (0..1) of the input faces\n"
    "  --faces N          stop at N faces or fewer\n"
    "  --vertices N       stop at N vertices or fewer\n"
    "  --max-factor F     remove only vertices whose priority is <= F (mesh units)\n"
    "  --auto             stop when only the last interval of the hash table is left\n"
    "  --max-error E[%]   guaranteed error: no point of the output farther than E from the\n"
    "                     input and none of the input farther than E from the output\n"
    "                     (mesh units, or % of the bounding-box diagonal); alone, or with\n"
    "                     a count target (whichever comes first). The bound the run\n"
    "                     certifies is printed\n"
    "options:\n"
    "  --mode surface|terrain|planar   3D average plane (default), 2.5D XY plane, 2D mesh plane\n"
    "  --intervals N                   hash-table intervals (default 1000)\n"
    "  --priority local-error|factor   sort by the local error of the planned re-triangulation\n"
    "                                  (default) or by the paper's evaluation factor\n"
    "  --fill best|projection          fill each hole with the best of the projection and the\n"
    "                                  fans (default) or with the paper's projection only\n"
    "  --mapping linear|log            factor -> interval mapping (default log)\n"
    "  --queue intervals|heap          hash table (default) or exact heap (reference)\n"
    "  --reprice auto|lazy|eager       a removal's queued neighbours are priced again when\n"
    "                                  popped (lazy) or at once (eager: the paper's way,\n"
    "                                  slower); auto (default): eager under 20 000 faces\n"
    "  --threads N                     threads to plan removals on (default 0: every core\n"
    "                                  the process may use); the output is the same for any N\n"
    "  --simplify-boundary             also remove boundary vertices (default: kept, unless\n"
    "                                  the kept border alone would take more than a quarter\n"
    "                                  of the faces asked for)\n"
    "  --keep-boundary                 keep every boundary vertex whatever the target\n"
    "  --no-slide                      leave kept vertices where the run left them (default:\n"
    "                                  after the run, a kept vertex may give its place to a\n"
    "                                  removed input vertex nearer the input)\n"
    "  --split-vertices seam|weld|keep vertices written twice at one position along a\n"
    "                                  seam: welded for the run, each side keeping its own\n"
    "                                  copies (seam), welded freely (weld: the default when\n"
    "                                  vertices hold nothing but a position), or left apart\n"
    "                                  as borders (keep)\n"
    "  --max-jump X                    stop short of a count target rather than take a\n"
    "                                  removal costing X times the dearest so far, X/2 once\n"
    "                                  the vetoes are eased (default 10; 0: the target at any\n"
    "                                  cost)\n"
    "  --error-bound                   track and print the certified error bound without\n"
    "                                  limiting it (what --max-error does, minus the limit)\n"
    "  --feature-angle DEG             keep edges whose faces turn more than DEG apart as\n"
    "                                  polylines, as texture seams always are (default 0: off);\n"
    "                                  also where per-corner normals make a hard edge (default\n"
    "                                  60; flat shading, one normal per face, makes none)\n"
    "  --progress / --quiet            progress on stderr: by default only when stderr is a\n"
    "                                  terminal (a bar, after the first second); --progress\n"
    "                                  elsewhere prints a line per 10 %\n"
    "  --json                          print one JSON line instead of the text report\n"
    "levels of detail (OUTPUT .glb: binary glTF 2.0, every attribute of the input):\n"
    "  --lods R,R,..|N                 one nested run: each level simplified from the finer\n"
    "                                  one (its vertices a subset of it), all in one .glb\n"
    "                                  sharing one vertex buffer, coarsest level first, bound\n"
    "                                  by MSFT_lod; N: N levels halving from 1 (the input).\n"
    "                                  Without --lods a .glb holds the --ratio level alone\n"
    "  --progressive [--base R]        a progressive mesh: the base (R of the faces, default\n"
    "                                  0.003) drawn by any glTF reader, then one record a\n"
    "                                  removed vertex, coarsest first, that puts it back\n"
    "                                  (VRS_mesh_progressive, docs/progressive.md): all of\n"
    "                                  them give the input exactly\n"
    "  --compress                      EXT_meshopt_compression (meshoptimizer's codec,\n"
    "                                  lossless: positions stay the input's floats); the\n"
    "                                  levels still stream coarsest first\n"
    "bigger than memory (tiled, out of core; with --ratio, --split-vertices):\n"
    "  --memory SIZE                   memory budget (512M, 2G, ...): a mesh that does not\n"
    "                                  fit is streamed into tiles simplified on local worker\n"
    "                                  processes and joined by input vertex id, written in the\n"
    "                                  input's format with every attribute; one that fits runs\n"
    "                                  in core as usual\n"
    "  --workers N                     worker processes (default: the cores)\n"
    "  --work-dir DIR                  where the tile files go, in a fresh folder removed after\n"
    "                                  (default: the output's folder; ~70 bytes a face)\n"
    "  --scheduler ADDRESS             run the tiles as tasks of a Dask cluster (needs the\n"
    "                                  Python package with dask and distributed; --work-dir\n"
    "                                  must be a path every worker can reach)\n"
    "  --ascii                         write ascii PLY (default binary)\n"
    "  --version                       print the version\n"
    "Options take their value as the next argument or after '=' (--ratio=0.1).\n";

// One line: what was wrong, and where the rest is (the whole help buries the message).
int usage_error(const std::string& msg) {
  std::fprintf(stderr, "vrsimplify: %s (see vrsimplify --help)\n", msg.c_str());
  return 2;
}

// The formats the writer knows, judged before any work: a typo costs no run.
bool writable(const std::string& path) {
  const size_t dot = path.rfind('.');
  if (dot == std::string::npos) return false;
  std::string ext = path.substr(dot + 1);
  for (char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == "ply" || ext == "off" || ext == "obj" || ext == "stl" || ext == "glb";
}

bool is_glb(const std::string& path) {
  return path.size() > 4 && (path.compare(path.size() - 4, 4, ".glb") == 0 ||
                             path.compare(path.size() - 4, 4, ".GLB") == 0);
}

bool parse_double(const char* s, double& out) {
  char* end = nullptr;
  out = std::strtod(s, &end);
  return end != s && *end == '\0' && std::isfinite(out);
}

bool parse_count(const char* s, size_t& out) {
  if (*s == '-' || *s == '\0') return false;
  char* end = nullptr;
  unsigned long long v = std::strtoull(s, &end, 10);
  out = static_cast<size_t>(v);
  return *end == '\0';
}

void print_text(const vrs::Report& r, double seconds_simplify, double seconds_total, double diag,
                bool bounded) {
  std::printf("input:   %zu vertices, %zu faces\n", r.input_vertices, r.input_faces);
  std::printf("output:  %zu vertices, %zu faces (%zu vertices removed)\n", r.vertices, r.faces,
              r.removed);
  std::printf("time:    %.3f s simplify, %.3f s total\n", seconds_simplify, seconds_total);
  if (r.constrained_edges)
    std::printf("seams:   %zu constrained edges (per-corner data differs, or creases), %zu "
                "vertices kept by them\n",
                r.constrained_edges, r.kept_constrained);
  std::printf("rejected removals: %zu (", r.rejected_total());
  for (int i = 0; i < vrs::RejectCount; ++i)
    std::printf("%s%s %zu", i ? ", " : "", vrs::reject_name(vrs::Reject(i)), r.rejected[i]);
  std::printf(")\nstopped: %s", vrs::stop_reason_name(r.stop));
  if (r.stop_cause != vrs::StopCause::None)
    std::printf(" (cause: %s)", vrs::stop_cause_name(r.stop_cause));
  std::printf(", target %s", r.target_reached ? "reached" : "NOT reached");
  if (!r.target_reached && r.target_faces)
    std::printf(" (%zu faces asked, %zu kept)", r.target_faces, r.faces);
  std::printf("\n");
  if (!r.stop_detail.empty()) std::printf("why:     %s\n", r.stop_detail.c_str());
  if (bounded)
    std::printf("bound:   %.6g (%.6g %% of the diagonal): no point of the output is farther "
                "from the input, nor of the input from the output (certified)\n",
                r.error_bound, diag > 0 ? 100.0 * r.error_bound / diag : 0.0);
  if (r.welded_vertices)
    std::printf("split:   %zu vertices written twice at one position welded for the run, each "
                "face keeping its own copy (--split-vertices)\n",
                r.welded_vertices);
  if (r.boundary_simplified)
    std::printf("border:  simplified too: kept, it alone would take more than a quarter of the "
                "faces asked for (--keep-boundary keeps it)\n");
  if (r.relaxed_removals)
    std::printf("relaxed: %zu removals after the input-normal veto was eased or lifted to reach "
                "the target\n",
                r.relaxed_removals);
  if (r.slid)
    std::printf("slid:    %zu kept vertices gave their place to a removed input vertex nearer "
                "the input (--no-slide: not)\n",
                r.slid);
  if (!r.message.empty()) std::printf("note:    %s\n", r.message.c_str());
}

} // namespace

int main(int argc, char** argv) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  std::string in, out;
  vrs::Options opt;
  bool json = false, ascii = false;
  std::optional<vrs::SplitVertices> split; // --split-vertices, else chosen from the vertices' data
  // `vrsimplify serve OUT.glb`: the viewer page lives in the Python package (vrsimplify.serve).
  if (argc >= 2 && std::strcmp(argv[1], "serve") == 0)
    return vrs_tool::exec_python_module("vrsimplify.serve", {argv + 2, argv + argc}, "serve",
                                        "pip install vrsimplify");
  // The progress bar: on a terminal by default; --progress forces it (logs), --quiet drops it.
  int progress = -1;
  int targets = 0;
  std::string not_ratio; // the first target option a tiled run does not take (all but --ratio)
  double max_error = 0;  // mesh units, or percent of the diagonal
  bool max_error_percent = false, error_bound = false;
  vrs_tool::TiledRequest tiled; // --memory / --scheduler
  std::vector<double> lods;     // --lods: levels of detail into one .glb
  bool compress = false;        // --compress: the .glb with EXT_meshopt_compression
  bool progressive = false;     // --progressive: a base mesh and one record a vertex, one .glb
  double base = 0.003;          // --base: the progressive base's share of the faces
  bool base_given = false;
  std::string not_tiled; // the first option a tiled run would not honour
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    // --opt=value: the value is what follows the '=', and only an option that takes one may
    // have it (a flag given "=x" is an error below, as an unknown option).
    std::string attached;
    bool has_attached = false;
    if (a.size() > 2 && a.compare(0, 2, "--") == 0) {
      const size_t eq = a.find('=');
      if (eq != std::string::npos) {
        attached = a.substr(eq + 1);
        a.resize(eq);
        has_attached = true;
      }
    }
    bool value_taken = false;
    auto value = [&]() -> const char* {
      value_taken = true;
      if (has_attached) return attached.c_str();
      if (i + 1 >= argc) return nullptr;
      return argv[++i];
    };
    const char* v = nullptr;
    // Options a tiled run does not honour yet: it refuses them by name (never ignores them).
    for (const char* o : {"--ascii", "--simplify-boundary", "--keep-boundary", "--max-jump",
                          "--error-bound", "--mode", "--queue", "--fill", "--priority", "--mapping",
                          "--feature-angle", "--reprice", "--intervals", "--threads", "--no-slide"})
      if (a == o && not_tiled.empty()) not_tiled = a;
    if (a == "--help" || a == "-h") {
      std::printf("%s", kUsage);
      return 0;
    } else if (a == "--version") {
      std::printf("vrsimplify %s\n", VRS_VERSION);
      return 0;
    } else if (a == "--compress") {
      compress = true;
    } else if (a == "--json") {
      json = true;
    } else if (a == "--ascii") {
      ascii = true;
    } else if (a == "--progress") {
      progress = 1;
    } else if (a == "--quiet") {
      progress = 0;
    } else if (a == "--simplify-boundary") {
      opt.simplify_boundary = true;
    } else if (a == "--keep-boundary") {
      opt.simplify_boundary_when_needed = false;
    } else if (a == "--no-slide") {
      opt.slide = false;
    } else if (a == "--split-vertices") {
      const std::string m = (v = value()) ? v : "";
      if (m == "seam" || m == "weld" || m == "keep")
        split = m == "seam"   ? vrs::SplitVertices::Seam
                : m == "weld" ? vrs::SplitVertices::Weld
                              : vrs::SplitVertices::Keep;
      else
        return usage_error("--split-vertices needs seam, weld or keep");
    } else if (a == "--max-jump") {
      if (!(v = value()) || !parse_double(v, opt.max_price_jump) || opt.max_price_jump < 0)
        return usage_error("--max-jump needs a number >= 0");
    } else if (a == "--error-bound") {
      error_bound = true;
    } else if (a == "--max-error") {
      if (not_ratio.empty()) not_ratio = a;
      std::string e = (v = value()) ? v : "";
      max_error_percent = !e.empty() && e.back() == '%';
      if (max_error_percent) e.pop_back();
      if (e.empty() || !parse_double(e.c_str(), max_error) || !(max_error > 0))
        return usage_error("--max-error needs a distance > 0, in mesh units or with % (of the "
                           "bounding-box diagonal)");
    } else if (a == "--progressive") {
      progressive = true;
    } else if (a == "--base") {
      if (!(v = value()) || !parse_double(v, base) || !(base > 0 && base <= 1))
        return usage_error("--base needs the base mesh's share of the faces, in (0, 1]");
      base_given = true;
    } else if (a == "--lods") {
      if (!(v = value()) || !vrs_tool::parse_lods(v, lods))
        return usage_error("--lods needs ratios in (0, 1] (0.5,0.1,0.01) or a count of levels "
                           "(halving from 1)");
    } else if (a == "--memory") {
      if (!(v = value()) || !(tiled.memory = vrs::tiled::parse_memory(v)))
        return usage_error("--memory needs a size such as 512M or 2G");
    } else if (a == "--workers") {
      size_t n = 0;
      if (!(v = value()) || !parse_count(v, n) || n < 1 || n > 1024)
        return usage_error("--workers needs a count in [1, 1024]");
      tiled.workers = int(n);
    } else if (a == "--work-dir") {
      if (!(v = value()) || !*v) return usage_error("--work-dir needs a folder");
      tiled.workdir = v;
    } else if (a == "--scheduler") {
      if (!(v = value()) || !*v) return usage_error("--scheduler needs a Dask scheduler address");
      tiled.scheduler = v;
    } else if (a == "--auto") {
      if (not_ratio.empty()) not_ratio = a;
      opt.target.kind = vrs::TargetKind::Auto;
      ++targets;
    } else if (a == "--ratio") {
      if (!(v = value()) || !parse_double(v, opt.target.ratio))
        return usage_error("--ratio needs a number in [0, 1]");
      opt.target.kind = vrs::TargetKind::Ratio;
      ++targets;
    } else if (a == "--faces") {
      if (not_ratio.empty()) not_ratio = a;
      if (!(v = value()) || !parse_count(v, opt.target.faces))
        return usage_error("--faces needs a count");
      opt.target.kind = vrs::TargetKind::Faces;
      ++targets;
    } else if (a == "--vertices") {
      if (not_ratio.empty()) not_ratio = a;
      if (!(v = value()) || !parse_count(v, opt.target.vertices))
        return usage_error("--vertices needs a count");
      opt.target.kind = vrs::TargetKind::Vertices;
      ++targets;
    } else if (a == "--max-factor") {
      if (not_ratio.empty()) not_ratio = a;
      if (!(v = value()) || !parse_double(v, opt.target.max_factor))
        return usage_error("--max-factor needs a number >= 0");
      opt.target.kind = vrs::TargetKind::MaxFactor;
      ++targets;
    } else if (a == "--mode") {
      if (!(v = value()) || !vrs::parse_mode(v, opt.mode))
        return usage_error("--mode must be surface, terrain or planar");
    } else if (a == "--queue") {
      if (!(v = value()) || !vrs::parse_queue(v, opt.tuning.queue))
        return usage_error("--queue must be intervals or heap");
    } else if (a == "--fill") {
      if (!(v = value()) || !vrs::parse_fill(v, opt.tuning.fill))
        return usage_error("--fill must be best or projection");
    } else if (a == "--priority") {
      if (!(v = value()) || !vrs::parse_priority(v, opt.tuning.priority))
        return usage_error("--priority must be factor or local-error");
    } else if (a == "--mapping") {
      if (!(v = value()) || !vrs::parse_mapping(v, opt.tuning.mapping))
        return usage_error("--mapping must be linear or log");
    } else if (a == "--feature-angle") {
      if (!(v = value()) || !parse_double(v, opt.feature_angle_deg))
        return usage_error("--feature-angle needs degrees in [0, 180]");
    } else if (a == "--reprice") {
      if (!(v = value()) ||
          (std::strcmp(v, "auto") && std::strcmp(v, "lazy") && std::strcmp(v, "eager")))
        return usage_error("--reprice must be auto, lazy or eager");
      opt.tuning.lazy_reevaluation = std::strcmp(v, "eager") != 0;
      opt.tuning.lazy_from_faces = !std::strcmp(v, "lazy") ? 0 : vrs::Tuning().lazy_from_faces;
    } else if (a == "--threads") {
      size_t n = 0;
      if (!(v = value()) || !parse_count(v, n) || n > 1024)
        return usage_error("--threads needs a count in [0, 1024]");
      opt.threads = static_cast<int>(n);
    } else if (a == "--intervals") {
      size_t n = 0;
      if (!(v = value()) || !parse_count(v, n) || n > (1u << 20))
        return usage_error("--intervals needs a count");
      opt.tuning.intervals = static_cast<int>(n);
    } else if (a.size() > 1 && a[0] == '-') { // "-" alone: standard output
      return usage_error("unknown option " + a);
    } else if (in.empty()) {
      in = a;
    } else if (out.empty()) {
      out = a;
    } else {
      return usage_error("unexpected argument " + a);
    }
    if (has_attached && !value_taken) return usage_error(a + " takes no value");
  }
  if (in.empty() || out.empty()) return usage_error("INPUT and OUTPUT are required");
  if (targets > 1) return usage_error("give at most one target");
  // "-": the mesh to standard output, in the input's format (binary PLY with --ascii unset),
  // written to a temporary file first; the report then goes to standard error.
  const bool to_stdout = out == "-";
  std::string stdout_file;
  if (to_stdout) {
    const size_t dot = in.rfind('.');
    const std::string ext = dot == std::string::npos ? "" : in.substr(dot);
    if (!writable("x" + ext))
      return usage_error("OUTPUT - writes the input's format, and " + in + " has none it writes");
    if (tiled.memory || !tiled.scheduler.empty())
      return usage_error("tiled runs (--memory, --scheduler) write a file, not standard output");
    const char* tmpdir = std::getenv("TMPDIR");
    stdout_file = std::string(tmpdir && *tmpdir ? tmpdir : "/tmp") + "/vrsimplify-stdout-" +
                  std::to_string(getpid()) + ext;
    out = stdout_file;
  }
  if (!writable(out))
    return usage_error("cannot write " + out +
                       ": the output must end in .ply, .off, .obj, .stl or .glb");
  if (!lods.empty() && !is_glb(out))
    return usage_error("--lods writes one .glb with every level: OUTPUT must end in .glb");
  if (progressive && !is_glb(out))
    return usage_error("--progressive writes a .glb: OUTPUT must end in .glb");
  if (base_given && !progressive) return usage_error("--base applies with --progressive");
  if (progressive && targets)
    return usage_error("--progressive takes the base's size as --base R, not --ratio or other "
                       "targets");
  if (progressive && (!lods.empty() || compress || error_bound))
    return usage_error("--progressive takes no --lods, --compress nor --error-bound: its "
                       "records refine the base vertex by vertex");
  if (compress && !is_glb(out))
    return usage_error("--compress applies to a .glb output (EXT_meshopt_compression)");
  if (is_glb(out)) {
    if (tiled.memory || !tiled.scheduler.empty())
      return usage_error("tiled runs (--memory, --scheduler) write the input's format, not .glb");
    if (ascii) return usage_error(".glb is binary: --ascii does not apply");
    if (targets && opt.target.kind != vrs::TargetKind::Ratio)
      return usage_error("a .glb takes its levels as --ratio R or --lods, not other targets");
    if (max_error > 0)
      return usage_error("a .glb takes no --max-error (--error-bound records "
                         "each level's bound)");
    vrs_tool::GlbRequest g;
    g.input = in, g.output = out, g.options = opt, g.json = json, g.error_bound = error_bound;
    g.compress = compress;
    g.progressive = progressive;
    if (progressive) opt.target.ratio = base;
    g.ratios = lods.empty() ? std::vector<double>{opt.target.ratio} : lods;
    if (lods.empty() && !(opt.target.ratio > 0 && opt.target.ratio <= 1))
      return usage_error("--ratio for a .glb must be in (0, 1]");
    return vrs_tool::run_glb(g);
  }
  const int mesh_fd = to_stdout ? dup(STDOUT_FILENO) : -1;
  if (to_stdout) {
    std::fflush(stdout);
    dup2(STDERR_FILENO, STDOUT_FILENO); // the report, and anything else printed, to stderr
  }
  if (max_error > 0 && targets == 0) { // the bound alone: as far as it allows
    opt.target.kind = vrs::TargetKind::Faces;
    opt.target.faces = 0;
    // No count to reach: the last resort, which lifts vetoes to reach one, has nothing to do.
    opt.relax_to_reach_target = false;
  }

  if (tiled.memory || !tiled.scheduler.empty()) {
    const uint64_t faces = vrs_tool::estimate_faces(in);
    if (!tiled.scheduler.empty() || !vrs::tiled::fits_in_core(faces, tiled.memory)) {
      if (!not_ratio.empty())
        return usage_error("tiled runs (--memory, --scheduler) take --ratio only, not " +
                           not_ratio);
      if (!not_tiled.empty())
        return usage_error("tiled runs (--memory, --scheduler) do not take " + not_tiled +
                           " yet; without --memory the run is in core");
      const std::string refusal = vrs::tiled::output_refusal(in, out);
      if (!refusal.empty()) return usage_error(refusal);
      tiled.input = in, tiled.output = out, tiled.ratio = opt.target.ratio;
      tiled.json = json;
      if (split)
        tiled.split_vertices = *split == vrs::SplitVertices::Weld   ? "weld"
                               : *split == vrs::SplitVertices::Keep ? "keep"
                                                                    : "seam";
      tiled.progress = progress == 1 || (progress == -1 && isatty(STDERR_FILENO));
      return vrs_tool::run_tiled(tiled);
    }
  }
  vrs_tool::LoadResult loaded = vrs_tool::load(in);
  if (!loaded.doc) {
    std::fprintf(stderr, "vrsimplify: %s\n", loaded.error.c_str());
    return 3;
  }
  vrs::Mesh mesh = vrs_tool::to_core(*loaded.doc);
  // A PLY's double coordinates, or an ascii output: the input's vertex records are kept aside
  // (vcglib's mesh holds float, and prints 6 digits), the core sees the doubles.
  const vrs_tool::ExactVertices exact(in, out, ascii);
  if (exact.has_double_positions()) {
    if (!exact.core_positions(mesh.vertex_count(), mesh.positions))
      std::fprintf(stderr,
                   "vrsimplify: note: coordinates beyond a float's precision read as float\n");
    else if (!exact.needed())
      std::fprintf(stderr,
                   "vrsimplify: note: the input has coordinates a float cannot hold; %s is "
                   "written with float ones (write the input's format to keep them exact)\n",
                   out.c_str());
  }
  const double diag = vrs::bounding_box_diagonal(mesh);
  opt.max_error = max_error_percent ? max_error / 100.0 * diag : max_error;
  if (error_bound && !(opt.max_error > 0)) opt.max_error = HUGE_VAL;
  // Texture coordinates and normals stored per corner: their seams (for normals: hard edges,
  // turning more than the feature angle or 60°) stay, new faces take the data of the corners
  // they replace (flat-shaded normals: their own).
  vrs_tool::set_feature_angle(*loaded.doc, opt.feature_angle_deg);
  opt.corner_sources = vrs_tool::has_corner_data(*loaded.doc);
  // Split vertices that hold nothing but a position, in faces whose corners hold nothing that
  // tells a seam's sides apart (flat shading holds nothing), are interchangeable: welded
  // freely, the per-corner data's seams found across split edges as across shared ones (the
  // faces read through the copies that stand for them). Others keep their sides (Seam).
  const bool own_data =
      vrs_tool::has_vertex_data(*loaded.doc, in) || vrs_tool::has_seam_data(*loaded.doc);
  opt.split_vertices = split      ? *split
                       : own_data ? vrs::SplitVertices::Seam
                                  : vrs::SplitVertices::Weld;
  std::vector<uint32_t> seams;
  if (opt.split_vertices == vrs::SplitVertices::Keep) {
    seams = vrs_tool::seams(*loaded.doc, mesh);
  } else {
    vrs::Mesh welded;
    welded.triangles = vrs::split_vertex_welded_triangles(mesh);
    seams = vrs_tool::seams(*loaded.doc, welded);
  }
  opt.constrained_edges = &seams;
  // Polygons are written back whole where the run leaves them (the slide leaves them so).
  const std::vector<uint8_t> polygon_faces =
      vrs_tool::polygon_faces(*loaded.doc, mesh.face_count());
  if (!polygon_faces.empty()) opt.polygon_faces = &polygon_faces;
  const bool terminal = isatty(STDERR_FILENO);
  vrs_tool::ProgressBar bar(progress == 1 || (progress == -1 && terminal), terminal);
  opt.progress = [&bar](float f) { return bar.update(f); };
  const auto t1 = clock::now();
  vrs::Report report = vrs::simplify(mesh, opt);
  bar.finish();
  const double seconds_simplify = std::chrono::duration<double>(clock::now() - t1).count();
  if (!report.ok) {
    std::fprintf(stderr, "vrsimplify: %s\n", report.message.c_str());
    vrs_tool::close(loaded.doc);
    return 1;
  }
  vrs_tool::apply(*loaded.doc, mesh, report);
  std::vector<uint32_t> kept(exact.needed() ? mesh.vertex_count() : 0); // output -> input vertex
  for (size_t v = 0; exact.needed() && v < report.remap.size(); ++v)
    if (report.remap[v] != vrs::kRemoved) kept[report.remap[v]] = uint32_t(v);
  std::string err = vrs_tool::save(*loaded.doc, out, ascii, &exact, &kept);
  vrs_tool::close(loaded.doc);
  if (!err.empty()) {
    std::fprintf(stderr, "vrsimplify: %s\n", err.c_str());
    return 3;
  }
  if (to_stdout) { // the mesh, whole, to the real standard output
    std::FILE* f = std::fopen(stdout_file.c_str(), "rb");
    char buf[1 << 16];
    size_t n;
    bool ok = f != nullptr;
    while (ok && (n = std::fread(buf, 1, sizeof buf, f)) > 0)
      ok = write(mesh_fd, buf, n) == ssize_t(n);
    if (f) std::fclose(f);
    std::remove(stdout_file.c_str());
    close(mesh_fd);
    if (!ok) {
      std::fprintf(stderr, "vrsimplify: cannot write to standard output\n");
      return 3;
    }
  }
  const double seconds_total = std::chrono::duration<double>(clock::now() - t0).count();
  if (json) {
    vrs::ReportContext context;
    context.seconds_simplify = seconds_simplify;
    context.seconds_total = seconds_total;
    context.diagonal = diag;
    context.bounded = opt.max_error > 0;
    std::printf("%s\n", vrs::report_json(report, context).c_str());
  } else {
    print_text(report, seconds_simplify, seconds_total, diag, opt.max_error > 0);
  }
  return 0;
}
