#include "filter_parameters.h"

#include <cmath>

namespace vrs_plugin {

void declare_parameters(const MeshModel& m, RichParameterList& par) {
  const int faces = m.cm.sfn > 0 ? m.cm.sfn : m.cm.fn;
  par.addParam(RichInt("TargetFaceNum", faces / 2, "Target number of faces",
                       "The desired final number of faces (default: half of them). Used unless "
                       "Percentage, Target vertices, Max factor or Auto stop is set."));
  par.addParam(RichFloat("TargetPerc", 0, "Percentage reduction (0..1)",
                         "If non zero, the desired final size as a fraction of the input faces "
                         "(0.1 keeps 10 %); overrides the target number of faces."));
  par.addParam(RichInt("TargetVertNum", 0, "Target number of vertices",
                       "If non zero, stop at this many vertices; overrides the face targets."));
  par.addParam(RichFloat("MaxFactor", 0, "Max priority (absolute)",
                         "If non zero, remove only vertices whose priority (see Priority; in "
                         "mesh units) is at most this; overrides the count targets."));
  par.addParam(RichBool("AutoStop", false, "Auto stop (last interval)",
                        "Stop by the paper's own rule: when only the last interval of the hash "
                        "table (the most important vertices) is left. Overrides every target."));
  par.addParam(RichEnum("Mode", 0,
                        QStringList() << "3D surface (average plane)"
                                      << "2.5D terrain (XY plane)"
                                      << "2D planar mesh",
                        "Mesh kind",
                        "3D: each hole is projected on its neighbours' average plane. 2.5D: on "
                        "the XY plane, factor = mean height difference (height fields). 2D: on "
                        "the mesh's own plane (flat meshes in any orientation)."));
  par.addParam(RichEnum("Priority", 0,
                        QStringList() << "Local error of the new patch"
                                      << "Evaluation factor (paper)",
                        "Priority",
                        "What the hash table sorts the vertices by. Local error: each removal is "
                        "planned first and priced by how far the new triangles stand from the "
                        "old ones, weighted by the patch's area (closer to the original). "
                        "Evaluation factor: the paper's mean distance of the vertex to its "
                        "neighbours' average plane (about 3x faster, larger error)."));
  par.addParam(RichInt("Intervals", 1000, "Hash table intervals",
                       "Number of intervals the factors are sorted into (at least 2). More "
                       "intervals follow the factor order more closely; Auto stop keeps the "
                       "last one."));
  par.addParam(RichBool("PreserveBoundary", true, "Preserve Boundary of the mesh",
                        "Keep every boundary vertex (the paper's rule), unless the kept boundary "
                        "alone would take more than a quarter of the faces asked for: then it is "
                        "simplified too, and the log says so. Off: boundary vertices may go too, "
                        "priced by the piece of the outline they cut off (with the evaluation "
                        "factor as priority, outline corners turning more than 30 degrees stay)."));
  par.addParam(RichBool("Selected", m.cm.sfn > 0, "Simplify only selected faces",
                        "Only vertices whose faces are all selected may be removed; the target "
                        "counts the whole mesh, as in Quadric Edge Collapse Decimation."));
  par.addParam(RichBool("AutoClean", true, "Post-simplification cleaning",
                        "Afterwards remove vertices no face uses (including ones the input had)."));
  par.addParam(RichInt("LODLevels", 1, "Levels of detail",
                       "If more than 1, make that many new layers, each simplified from the "
                       "previous one by the same reduction; the input layer is left untouched."));
  if (!kScriptsListEveryParameter)
    par.addParam(RichFloat("FeatureAngle", 0, "Crease angle (degrees)",
                           "If non zero, edges whose two faces turn more than this many degrees "
                           "apart are kept as polylines, as texture seams always are: a vertex "
                           "on such a crease goes only along it (vtkDecimatePro's feature "
                           "angle). 0 = off."));
  if (!kScriptsListEveryParameter)
    par.addParam(RichFloat("MaxError", 0, "Max error (% of the diagonal)",
                           "If non zero, a guaranteed error: no point of the result farther "
                           "than this from the input surface, and no point of the input "
                           "farther than this from the result (symmetric Hausdorff distance, "
                           "in percent of the bounding-box diagonal). With a face or vertex "
                           "target too, whichever comes first stops. The log and the result "
                           "give the bound the run certifies. 0 = off."));
}

QString read_parameters(const RichParameterList& par, const CMeshO& m, FilterSettings& s) {
  const int face_target = par.getInt("TargetFaceNum");
  const double perc = par.getFloat("TargetPerc");
  s.target_vertices = par.getInt("TargetVertNum");
  s.max_factor = par.getFloat("MaxFactor");
  s.auto_stop = par.getBool("AutoStop");
  const int mode = par.getEnum("Mode");
  const int priority = par.getEnum("Priority");
  s.intervals = par.getInt("Intervals");
  s.preserve_boundary = par.getBool("PreserveBoundary");
  s.selected = par.getBool("Selected");
  s.auto_clean = par.getBool("AutoClean");
  s.lod_levels = par.getInt("LODLevels");
  s.feature_angle = par.hasParameter("FeatureAngle") ? par.getFloat("FeatureAngle") : 0.0;
  s.max_error = par.hasParameter("MaxError") ? par.getFloat("MaxError") : 0.0;
  s.input_faces = m.fn;
  s.input_vertices = m.vn;

  if (face_target < 0)
    return QString("Target number of faces must be >= 0, got %1.").arg(face_target);
  if (!(perc >= 0 && perc <= 1))
    return QString("Percentage reduction must be in [0, 1], got %1.").arg(perc);
  if (s.target_vertices < 0)
    return QString("Target number of vertices must be >= 0, got %1.").arg(s.target_vertices);
  if (!(s.max_factor >= 0 && std::isfinite(s.max_factor)))
    return QString("Max priority must be >= 0, got %1.").arg(s.max_factor);
  if (mode < 0 || mode > 2) return QString("Unknown mesh kind %1.").arg(mode);
  s.mode = static_cast<vrs::Mode>(mode);
  if (priority < 0 || priority > 1) return QString("Unknown priority %1.").arg(priority);
  s.priority = priority == 0 ? vrs::Priority::LocalError : vrs::Priority::Factor;
  if (s.intervals < 2 || s.intervals > (1 << 20))
    return QString("Hash table intervals must be in [2, 1048576], got %1.").arg(s.intervals);
  if (s.lod_levels < 1 || s.lod_levels > 16)
    return QString("Levels of detail must be in [1, 16], got %1.").arg(s.lod_levels);
  if (!(s.feature_angle >= 0 && s.feature_angle <= 180))
    return QString("Crease angle must be in [0, 180] degrees, got %1.").arg(s.feature_angle);
  if (!(s.max_error >= 0 && s.max_error <= 100))
    return QString("Max error must be in [0, 100] % of the diagonal, got %1.").arg(s.max_error);
  if (s.selected && m.sfn == 0)
    return "Simplify only selected faces is on, but no face is selected.";

  // As Quadric Edge Collapse Decimation: the percentage is of all faces, and with a selection
  // the target is what the whole mesh should have once the selection lost its share.
  int target = perc > 0 ? int(std::lround(m.fn * perc)) : face_target;
  if (s.selected) target = std::max(0, m.fn - (m.sfn - target));
  s.target_faces = target;
  return {};
}

vrs::Options FilterSettings::options_for(int level, int faces, int vertices) const {
  vrs::Options o;
  o.mode = mode;
  o.tuning.priority = priority;
  o.tuning.intervals = intervals;
  o.simplify_boundary = !preserve_boundary;
  o.feature_angle_deg = feature_angle;
  vrs::Target& t = o.target;
  // Later levels repeat the first level's reduction on the previous level.
  auto scaled = [&](int first_target, int input, int now) {
    if (level == 1 || input == 0) return size_t(std::max(0, first_target));
    return size_t(std::llround(double(first_target) / double(input) * double(now)));
  };
  if (auto_stop) {
    t.kind = vrs::TargetKind::Auto;
  } else if (max_factor > 0) {
    t.kind = vrs::TargetKind::MaxFactor;
    t.max_factor = max_factor;
  } else if (target_vertices > 0) {
    t.kind = vrs::TargetKind::Vertices;
    t.vertices = scaled(target_vertices, input_vertices, vertices);
  } else {
    t.kind = vrs::TargetKind::Faces;
    t.faces = scaled(target_faces, input_faces, faces);
  }
  return o;
}

} // namespace vrs_plugin
