#include "filter_vertex_removal.h"

#include <QFileInfo>

#include <chrono>
#include <cmath>
#include <exception>

#include "cmesh_bridge.h"
#include "filter_parameters.h"
#include "vrs/simplify.h"

using vrs_plugin::FilterSettings;

FilterVertexRemovalPlugin::FilterVertexRemovalPlugin() {
  typeList << FP_VERTEX_REMOVAL;
  for (FilterIDType t : types())
    actionList << new QAction(filterName(t), this);
}

QString FilterVertexRemovalPlugin::pluginName() const {
  return "FilterVertexRemoval";
}

QString FilterVertexRemovalPlugin::filterName(FilterIDType) const {
  return tr("Simplification: Vertex Removal Decimation");
}

QString FilterVertexRemovalPlugin::filterInfo(FilterIDType) const {
  return tr(
      "Simplify a triangle mesh by removing vertices: the kept vertices are a subset of the "
      "input, untouched, so colors, normals, quality and texture coordinates survive exactly. "
      "Each vertex gets an <i>evaluation factor</i> (its mean distance to its neighbours along the "
      "normal of their average plane; the XY plane for 2.5D terrains), vertices go into a hash "
      "table of intervals, the first vertex of the lowest interval is removed and its hole is "
      "projected on the plane and re-triangulated (fan if convex, ear clipping otherwise), then "
      "its neighbours are re-evaluated. Linear time. Boundary vertices are kept by default; "
      "removals that would fold, flip or make the mesh non-manifold are refused."
      "<br><br>See:<br>"
      "<i>Bo&scaron;tjan Pivec, Vid Domiter</i><br>"
      "<b>\"A General Simplification Algorithm\"</b><br>"
      "University of Maribor.<br><br>"
      "<i>William J. Schroeder, Jonathan A. Zarge, William E. Lorensen</i><br>"
      "<b>\"Decimation of Triangle Meshes\"</b><br>"
      "Computer Graphics (SIGGRAPH '92), vol. 26, no. 2, 1992.");
}

MeshFilterInterface::FilterClass FilterVertexRemovalPlugin::getClass(QAction*) {
  return MeshFilterInterface::Remeshing;
}

int FilterVertexRemovalPlugin::getPreConditions(QAction*) const {
  return MeshModel::MM_FACENUMBER;
}

int FilterVertexRemovalPlugin::postCondition(QAction*) const {
  return MeshModel::MM_GEOMETRY_AND_TOPOLOGY_CHANGE;
}

void FilterVertexRemovalPlugin::initParameterSet(QAction*, MeshModel& m, RichParameterList& par) {
  vrs_plugin::declare_parameters(m, par);
}

bool FilterVertexRemovalPlugin::applyFilter(QAction*, MeshDocument& md,
                                            const RichParameterList& par, vcg::CallBackPos* cb) {
  // Anything thrown here would abort the whole MeshLab session with the user's unsaved work.
  try {
    if (apply_checked(md, par, cb)) return true;
  } catch (const std::bad_alloc&) {
    errorMessage = "Vertex Removal Decimation: out of memory; the mesh was not changed.";
  } catch (const std::exception& e) {
    errorMessage =
        QString("Vertex Removal Decimation failed (%1); the mesh was not changed.").arg(e.what());
  } catch (...) {
    errorMessage = "Vertex Removal Decimation failed; the mesh was not changed.";
  }
  // meshlabserver prints the log but not the error message: say it in both.
  Log(GLLogStream::WARNING, "%s", qUtf8Printable(errorMessage));
  return false;
}

namespace {

// Label of LOD layer `level` made from `base`: MeshLab takes what follows a '.' for a format.
QString lod_label(const QString& base, int level) {
  QString stem = QFileInfo(base).completeBaseName();
  stem.replace('.', '_');
  if (stem.isEmpty()) stem = "mesh";
  return QString("%1_LOD%2").arg(stem).arg(level);
}

} // namespace

bool FilterVertexRemovalPlugin::apply_checked(MeshDocument& md, const RichParameterList& par,
                                              vcg::CallBackPos* cb) {
  MeshModel* input = md.mm();
  if (input == nullptr || input->cm.fn == 0) {
    errorMessage = "Vertex Removal Decimation needs a mesh with faces.";
    return false;
  }
  FilterSettings s;
  QString problem = vrs_plugin::read_parameters(par, input->cm, s);
  if (!problem.isEmpty()) {
    errorMessage = problem;
    return false;
  }

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
          md.delMesh(c);
    }
  } rollback{md, created};
  MeshModel* source = input;
  for (int level = 1; level <= levels; ++level) {
    MeshModel* target = input;
    if (levels > 1) {
      target = md.addNewMesh("", lod_label(input->label(), level), false);
      target->updateDataMask(source->dataMask());
      vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(target->cm, source->cm);
      created.push_back(target);
    }
    int shown = -1;
    auto progress = [&](float f) {
      int percent = std::min(99, int(100.0f * (float(level - 1) + f) / float(levels)));
      if (percent != shown) cb(shown = percent, "Vertex Removal Decimation"); // once a percent
      return true; // MeshLab 2020.09 hosts cannot cancel
    };
    QString error = simplify_layer(*target, s, level, progress);
    if (!error.isEmpty()) {
      errorMessage = error;
      return false;
    }
    source = target;
  }
  rollback.done = true;
  cb(100, "Vertex Removal Decimation done");
  return true;
}

QString FilterVertexRemovalPlugin::simplify_layer(MeshModel& m, const FilterSettings& s, int level,
                                                  const std::function<bool(float)>& progress) {
  vrs_plugin::CoreCopy copy = vrs_plugin::to_core(m.cm);
  vrs::Options o = s.options_for(level, m.cm.fn, m.cm.vn);
  std::vector<uint8_t> lock;
  if (s.selected) {
    lock = vrs_plugin::lock_outside_selection(m.cm, copy);
    o.locked = &lock;
  }
  o.progress = progress;
  vrs::Mesh mesh = copy.mesh;
  const auto t0 = std::chrono::steady_clock::now();
  vrs::Report r = vrs::simplify(mesh, o);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!r.ok)
    return QString("Vertex Removal Decimation: %1; the mesh was not changed.")
        .arg(QString::fromStdString(r.message));

  vrs_plugin::apply(m.cm, copy, mesh, r, s.selected);
  if (s.auto_clean) {
    int unreferenced = vcg::tri::Clean<CMeshO>::RemoveUnreferencedVertex(m.cm);
    if (unreferenced)
      Log("Post-simplification cleaning: removed %d unreferenced vertices", unreferenced);
    vcg::tri::Allocator<CMeshO>::CompactEveryVector(m.cm);
  }
  m.UpdateBoxAndNormals();
  vcg::tri::UpdateNormal<CMeshO>::NormalizePerFace(m.cm);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexFromCurrentFaceNormal(m.cm);
  vcg::tri::UpdateNormal<CMeshO>::NormalizePerVertex(m.cm);

  QString level_text =
      s.lod_levels > 1 ? QString(" (level %1, layer %2)").arg(level).arg(m.label()) : "";
  Log("Vertex Removal Decimation%s: %zu -> %zu faces, %zu -> %zu vertices in %.3f s",
      qUtf8Printable(level_text), r.input_faces, size_t(m.cm.fn), r.input_vertices, size_t(m.cm.vn),
      seconds);
  QString rejected;
  for (int i = 0; i < vrs::RejectCount; ++i)
    rejected += QString("%1%2 %3")
                    .arg(i ? ", " : "")
                    .arg(vrs::reject_name(vrs::Reject(i)))
                    .arg(r.rejected[i]);
  Log("Rejected removals: %zu (%s)", r.rejected_total(), qUtf8Printable(rejected));
  if (r.target_reached) {
    Log("Stopped: %s", vrs::stop_reason_name(r.stop));
  } else {
    Log(GLLogStream::WARNING,
        "Target not reached (%s): every remaining vertex is kept (boundary, non-manifold, "
        "locked or of too high valence) or its removal would fold, flip or break the topology",
        vrs::stop_reason_name(r.stop));
  }
  if (!r.message.empty()) Log(GLLogStream::WARNING, "Input: %s", r.message.c_str());
  return {};
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterVertexRemovalPlugin)
