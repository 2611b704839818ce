#include "vertex_removal_filter.h"

#include <QFileInfo>

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/append.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <limits>
#include <new>

#include "cmesh_bridge.h"
#include "filter_parameters.h"
#include "vrs/simplify.h"

namespace vrs_plugin {

QString filter_name() {
  return "Simplification: Vertex Removal Decimation";
}

QString python_filter_name() {
  return "meshing_decimation_vertex_removal";
}

QString filter_info() {
  return "Simplify a triangle mesh by removing vertices: the kept vertices are a subset of the "
         "input, untouched, so colors, normals, quality and texture coordinates survive exactly. "
         "Each removal is planned first (the hole filled by the paper's projection or by a fan "
         "from a neighbour) and priced by the <i>local error</i> of that patch (or by the "
         "paper's <i>evaluation factor</i>); vertices go into the paper's hash table of "
         "intervals by that price and the lowest go first. Boundary vertices are kept by "
         "default; removals that would fold over, flip or break manifoldness are refused. Max "
         "error (MeshLab 2022.02 and later) guarantees the Hausdorff distance to the input."
         "<br><br>See:<br>"
         "<i>Bo&scaron;tjan Pivec, Vid Domiter</i><br>"
         "<b>\"A General Simplification Algorithm\"</b><br>"
         "University of Maribor.<br><br>"
         "<i>William J. Schroeder, Jonathan A. Zarge, William E. Lorensen</i><br>"
         "<b>\"Decimation of Triangle Meshes\"</b><br>"
         "Computer Graphics (SIGGRAPH '92), vol. 26, no. 2, 1992.";
}

namespace {

// The last run's report on this thread, as the core writes it (JSON): pymeshlab's result map
// takes no strings, so vrsimplify.pymeshlab reads the stop's detail and cause through
// vrs_filter_last_report().
thread_local std::string last_report;

// Label of LOD layer `level` made from `base`: MeshLab takes what follows a '.' for a format.
QString lod_label(const QString& base, int level) {
  QString stem = QFileInfo(base).completeBaseName();
  stem.replace('.', '_');
  if (stem.isEmpty()) stem = "mesh";
  return QString("%1_LOD%2").arg(stem).arg(level);
}

// Totals over the levels of one application.
struct Totals {
  size_t removed = 0, rejected[vrs::RejectCount] = {};
  size_t kept_boundary = 0, kept_nonmanifold = 0, kept_locked = 0, kept_high_valence = 0;
  size_t kept_constrained = 0, constrained_edges = 0, relaxed_removals = 0, slid = 0;
  size_t target_faces = 0; // the last level's
  double max_priority = 0, seconds = 0;
  double error_bound = 0, diagonal = 0; // summed over the levels: each is bounded from the last
  bool target_reached = true, boundary_simplified = false;
  vrs::StopReason stop = vrs::StopReason::TargetReached; // of the last level
};

class Application {
 public:
  Application(MeshDocument& md, const Host& host) : md_(md), host_(host) {}

  Outcome run(const RichParameterList& par);

 private:
  QString simplify_layer(MeshModel& m, const FilterSettings& s, int level,
                         const std::function<bool(float)>& progress);
  void log(const QString& text) const { host_.log(GLLogStream::FILTER, text); }
  void warn(const QString& text) const { host_.log(GLLogStream::WARNING, text); }

  MeshDocument& md_;
  const Host& host_;
  Totals totals_;
};

Outcome Application::run(const RichParameterList& par) {
  Outcome out;
  MeshModel* input = md_.mm();
  if (input == nullptr || input->cm.fn == 0) {
    out.error = "Vertex Removal Decimation needs a mesh with faces.";
    return out;
  }
  FilterSettings s;
  out.error = read_parameters(par, input->cm, s);
  if (!out.error.isEmpty()) return out;
  const size_t input_faces = size_t(input->cm.fn), input_vertices = size_t(input->cm.vn);

  const int levels = s.lod_levels;
  std::vector<MeshModel*> created;
  // A failure (returned or thrown) takes back the layers this call made; the input layer is
  // only written to when it is the one being simplified, and then only once it has succeeded.
  struct Rollback {
    MeshDocument& md;
    std::vector<MeshModel*>& created;
    bool done = false;
    ~Rollback() {
      if (!done)
        for (MeshModel* c : created)
          delete_layer(md, c);
    }
  } rollback{md_, created};
  MeshModel* source = input;
  for (int level = 1; level <= levels; ++level) {
    MeshModel* target = input;
    if (levels > 1) {
      target = md_.addNewMesh("", lod_label(input->label(), level), false);
      created.push_back(target);
      target->updateDataMask(source->dataMask());
      vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(target->cm, source->cm);
    }
    int shown = -1;
    auto progress = [&](float f) {
      int percent = std::min(99, int(100.0f * (float(level - 1) + f) / float(levels)));
      if (host_.progress && percent != shown) // once a percent
        host_.progress(shown = percent, "Vertex Removal Decimation");
      return true; // no MeshLab host can cancel a filter
    };
    out.error = simplify_layer(*target, s, level, progress);
    if (!out.error.isEmpty()) return out;
    source = target;
  }
  rollback.done = true;
  if (host_.progress) host_.progress(100, "Vertex Removal Decimation done");

  // pymeshlab hands back only bool, int and floating-point values (measured: strings and
  // 64-bit integers are dropped), hence ints and the stop reason as its number.
  auto count = [](size_t n) { return int(std::min<size_t>(n, std::numeric_limits<int>::max())); };
  FilterResult& r = out.result;
  r["input_faces"] = count(input_faces);
  r["input_vertices"] = count(input_vertices);
  r["output_faces"] = source->cm.fn;
  r["output_vertices"] = source->cm.vn;
  r["target_faces"] = count(totals_.target_faces);
  // The CLI's JSON and the numpy API's keys (docs/report.md); nested groups flattened
  // (rejected_fold, kept_boundary, ...): pymeshlab takes flat numbers only.
  r["removed"] = count(totals_.removed);
  r["levels"] = levels;
  r["stop_reason"] = int(totals_.stop);
  r["target_reached"] = totals_.target_reached;
  r["boundary_simplified"] = totals_.boundary_simplified;
  size_t rejected = 0;
  for (int i = 0; i < vrs::RejectCount; ++i) {
    r[std::string("rejected_") + vrs::reject_name(vrs::Reject(i))] = count(totals_.rejected[i]);
    rejected += totals_.rejected[i];
  }
  r["rejected_total"] = count(rejected);
  r["kept_boundary"] = count(totals_.kept_boundary);
  r["kept_nonmanifold"] = count(totals_.kept_nonmanifold);
  r["kept_locked"] = count(totals_.kept_locked);
  r["kept_high_valence"] = count(totals_.kept_high_valence);
  r["kept_constrained"] = count(totals_.kept_constrained);
  r["constrained_edges"] = count(totals_.constrained_edges);
  r["max_removed_factor"] = totals_.max_priority;
  r["relaxed_removals"] = count(totals_.relaxed_removals);
  r["slid"] = count(totals_.slid);
  // With MaxError: the certified bound of the last level against the input (mesh units, and
  // in % of the input's diagonal). Without, no key: a bound not tracked is never "0".
  if (s.max_error > 0) {
    r["error_bound"] = totals_.error_bound;
    r["error_bound_percent"] =
        totals_.diagonal > 0 ? 100.0 * totals_.error_bound / totals_.diagonal : 0.0;
  }
  r["seconds_simplify"] = totals_.seconds;
  out.ok = true;
  return out;
}

QString Application::simplify_layer(MeshModel& m, const FilterSettings& s, int level,
                                    const std::function<bool(float)>& progress) {
  CoreCopy copy = to_core(m.cm);
  vrs::Options o = s.options_for(level, m.cm.fn, m.cm.vn);
  // Texture coordinates, normals and colors stored per face corner: the edges where they
  // differ (normals: turn past the feature angle, or 60°) are seams the core must keep, and
  // new faces take the data of the corners they replace (flat-shaded normals: their own).
  const vrs_vcg::CornerData data = corner_data(m, s.feature_angle);
  const std::vector<uint32_t> seam_edges = seams(m.cm, copy, data);
  o.constrained_edges = &seam_edges;
  o.corner_sources = data.any();
  const std::vector<uint8_t> lock = vertex_locks(m.cm, copy, s.selected);
  if (!lock.empty()) o.locked = &lock;
  const std::vector<uint8_t> polygons = polygon_faces(m.cm, copy);
  if (!polygons.empty()) o.polygon_faces = &polygons;
  o.progress = progress;
  vcg::tri::UpdateBounding<CMeshO>::Box(m.cm);
  if (level == 1) totals_.diagonal = m.cm.bbox.Diag();
  // The same distance at every level: the levels' bounds add up (log and result).
  if (s.max_error > 0) o.max_error = s.max_error / 100.0 * totals_.diagonal;
  vrs::Mesh mesh = copy.mesh;
  const auto t0 = std::chrono::steady_clock::now();
  vrs::Report r = vrs::simplify(mesh, o);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!r.ok)
    return QString("Vertex Removal Decimation: %1; the mesh was not changed.")
        .arg(QString::fromStdString(r.message));

  apply(m.cm, copy, mesh, r, s.selected, data);
  if (s.auto_clean) {
    int unreferenced = vcg::tri::Clean<CMeshO>::RemoveUnreferencedVertex(m.cm);
    if (unreferenced)
      log(QString("Post-simplification cleaning: removed %1 unreferenced vertices")
              .arg(unreferenced));
    vcg::tri::Allocator<CMeshO>::CompactEveryVector(m.cm);
  }
  update_box_and_normals(m);
  vcg::tri::UpdateNormal<CMeshO>::NormalizePerFace(m.cm);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexFromCurrentFaceNormal(m.cm);
  vcg::tri::UpdateNormal<CMeshO>::NormalizePerVertex(m.cm);

  totals_.removed += r.removed;
  for (int i = 0; i < vrs::RejectCount; ++i)
    totals_.rejected[i] += r.rejected[i];
  totals_.kept_boundary += r.kept_boundary;
  totals_.kept_nonmanifold += r.kept_nonmanifold;
  totals_.kept_locked += r.kept_locked;
  totals_.kept_high_valence += r.kept_high_valence;
  totals_.kept_constrained += r.kept_constrained;
  totals_.relaxed_removals += r.relaxed_removals;
  totals_.slid += r.slid;
  totals_.constrained_edges = std::max(totals_.constrained_edges, r.constrained_edges);
  totals_.max_priority = std::max(totals_.max_priority, r.max_removed_factor);
  totals_.error_bound += r.error_bound;
  totals_.seconds += seconds;
  totals_.target_reached = totals_.target_reached && r.target_reached;
  totals_.target_faces = r.target_faces;
  vrs::ReportContext context;
  context.seconds_simplify = seconds;
  context.diagonal = totals_.diagonal;
  context.bounded = o.max_error > 0;
  last_report = vrs::report_json(r, context);
  totals_.stop = r.stop;
  totals_.boundary_simplified = totals_.boundary_simplified || r.boundary_simplified;

  QString level_text =
      s.lod_levels > 1 ? QString(" (level %1, layer %2)").arg(level).arg(m.label()) : "";
  log(QString("Vertex Removal Decimation%1: %2 -> %3 faces, %4 -> %5 vertices in %6 s")
          .arg(level_text)
          .arg(r.input_faces)
          .arg(m.cm.fn)
          .arg(r.input_vertices)
          .arg(m.cm.vn)
          .arg(seconds, 0, 'f', 3));
  QString rejected;
  for (int i = 0; i < vrs::RejectCount; ++i)
    rejected += QString("%1%2 %3")
                    .arg(i ? ", " : "")
                    .arg(vrs::reject_name(vrs::Reject(i)))
                    .arg(r.rejected[i]);
  log(QString("Rejected removals: %1 (%2)").arg(r.rejected_total()).arg(rejected));
  if (r.constrained_edges)
    log(QString("Seams and creases: %1 constrained edges (%2%3), %4 vertices kept by them")
            .arg(r.constrained_edges)
            .arg(data.any() ? "where texture coordinates, normals or colors per corner differ" : "")
            .arg(s.feature_angle > 0 ? QString("%1edges turning over %2 degrees")
                                           .arg(data.any() ? ", and " : "")
                                           .arg(s.feature_angle)
                                     : "")
            .arg(r.kept_constrained));
  if (r.target_reached) {
    log(QString("Stopped: %1").arg(vrs::stop_reason_name(r.stop)));
  } else {
    warn(QString("Target not reached (%1, cause: %2): %3")
             .arg(vrs::stop_reason_name(r.stop))
             .arg(vrs::stop_cause_name(r.stop_cause))
             .arg(r.stop_detail.empty() ? QString("stopped before the target")
                                        : QString::fromStdString(r.stop_detail)));
  }
  if (o.max_error > 0)
    log(QString("Certified error bound: %1 (%2 % of the diagonal): no point of the result is "
                "farther from the input, nor of the input from the result%3")
            .arg(totals_.error_bound)
            .arg(totals_.diagonal > 0 ? 100.0 * totals_.error_bound / totals_.diagonal : 0.0)
            .arg(level > 1 ? " (the levels' bounds added up)" : ""));
  if (r.boundary_simplified)
    log("Boundary simplified too: kept, it alone would have taken more than a quarter of the "
        "faces asked for");
  if (r.relaxed_removals)
    log(QString("%1 removals needed the input-normal veto lifted to reach the target")
            .arg(r.relaxed_removals));
  if (r.slid)
    log(QString("%1 kept vertices gave their place to a removed input vertex nearer the input")
            .arg(r.slid));
  if (!r.message.empty()) warn(QString("Input: %1").arg(QString::fromStdString(r.message)));
  return {};
}

} // namespace

Outcome apply_vertex_removal(MeshDocument& md, const RichParameterList& par, const Host& host) {
  last_report.clear();
  // Anything thrown here would abort the host (the GUI with the user's unsaved work, or the
  // Python interpreter); the rollback has already restored the document when we get here.
  Outcome out;
  try {
    return Application(md, host).run(par);
  } catch (const std::bad_alloc&) {
    out.error = "Vertex Removal Decimation: out of memory; the mesh was not changed.";
  } catch (const std::exception& e) {
    out.error =
        QString("Vertex Removal Decimation failed (%1); the mesh was not changed.").arg(e.what());
  } catch (...) {
    out.error = "Vertex Removal Decimation failed; the mesh was not changed.";
  }
  return out;
}

} // namespace vrs_plugin

extern "C" __attribute__((visibility("default"))) const char* vrs_filter_last_report() {
  return vrs_plugin::last_report.c_str();
}
