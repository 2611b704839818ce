#include "core_arrays.h"

#include <cmath>

namespace vrs_py {

namespace {

template <class T> const T* element(const AnyArray& a, size_t i, size_t j) {
  const T* base = static_cast<const T*>(a.data());
  return base + int64_t(i) * a.stride(0) + int64_t(j) * a.stride(1);
}

void check_rows(const AnyArray& a, const char* what, size_t columns) {
  if (a.ndim() != 2 || a.shape(1) != columns)
    throw nb::value_error(
        (std::string(what) + " must be an (n, " + std::to_string(columns) + ") array").c_str());
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

} // namespace

std::vector<float> read_positions(const AnyArray& a) {
  check_rows(a, "mesh_vertices", 3);
  const size_t n = a.shape(0);
  if (a.dtype() == nb::dtype<float>()) {
    std::vector<float> out(3 * n);
    for (size_t i = 0; i < n; ++i)
      for (size_t j = 0; j < 3; ++j)
        out[3 * i + j] = *element<float>(a, i, j);
    return out;
  }
  if (a.dtype() != nb::dtype<double>())
    throw nb::value_error("mesh_vertices must be float32 or float64");
  // Doubles as the command line reads a file's: the same run, whatever reads the mesh.
  std::vector<double> xyz(3 * n);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < 3; ++j)
      xyz[3 * i + j] = *element<double>(a, i, j);
  return vrs::float_positions(xyz.data(), n);
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

std::vector<int64_t> signed_indices(const std::vector<uint32_t>& v) {
  std::vector<int64_t> out(v.size());
  for (size_t i = 0; i < v.size(); ++i)
    out[i] = v[i] == vrs::kRemoved ? -1 : int64_t(v[i]);
  return out;
}

// The report as the core writes it for every front end (docs/report.md), read back as a dict.
nb::dict report_dict(const vrs::Report& r, bool bounded, double seconds, double diagonal) {
  vrs::ReportContext context;
  context.seconds_simplify = seconds;
  context.diagonal = diagonal;
  context.bounded = bounded;
  nb::dict d =
      nb::cast<nb::dict>(nb::module_::import_("json").attr("loads")(vrs::report_json(r, context)));
  // Not tracked: None in Python (typed keys are always there), never 0.0.
  d.attr("setdefault")("error_bound", nb::none());
  d.attr("setdefault")("error_bound_percent", nb::none());
  return d;
}

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

std::vector<uint32_t> read_vector(const AnyArray& a, size_t bound, const char* what) {
  if (a.ndim() != 1) throw nb::value_error((std::string(what) + " must be a 1-D array").c_str());
  std::vector<uint32_t> out(a.shape(0));
  const nb::dlpack::dtype t = a.dtype();
  for (size_t i = 0; i < out.size(); ++i) {
    const int64_t stride = a.stride(0);
    int64_t v;
    if (t == nb::dtype<int64_t>())
      v = static_cast<const int64_t*>(a.data())[int64_t(i) * stride];
    else if (t == nb::dtype<int32_t>())
      v = static_cast<const int32_t*>(a.data())[int64_t(i) * stride];
    else if (t == nb::dtype<uint32_t>())
      v = static_cast<const uint32_t*>(a.data())[int64_t(i) * stride];
    else
      throw nb::value_error((std::string(what) + " must hold 32- or 64-bit integers").c_str());
    if (v < 0 || uint64_t(v) >= bound)
      throw nb::value_error((std::string(what) + " has index " + std::to_string(v) +
                             ", out of range for " + std::to_string(bound))
                                .c_str());
    out[i] = uint32_t(v);
  }
  return out;
}

std::vector<float> read_floats(const AnyArray& a, size_t rows, size_t columns, const char* what) {
  if (a.ndim() != 2 || a.shape(0) != rows || a.shape(1) != columns)
    throw nb::value_error((std::string(what) + " must be a (" + std::to_string(rows) + ", " +
                           std::to_string(columns) + ") array")
                              .c_str());
  const bool f32 = a.dtype() == nb::dtype<float>();
  if (!f32 && a.dtype() != nb::dtype<double>())
    throw nb::value_error((std::string(what) + " must be float32 or float64").c_str());
  std::vector<float> out(rows * columns);
  for (size_t i = 0; i < rows; ++i)
    for (size_t j = 0; j < columns; ++j)
      out[columns * i + j] = f32 ? *element<float>(a, i, j) : float(*element<double>(a, i, j));
  return out;
}

RunInput read_run_input(const AnyArray& vertices, const AnyArray& faces, const AnyArray* seams,
                        const AnyArray* corner_keys) {
  RunInput in;
  in.mesh.positions = read_positions(vertices);
  const size_t n = in.mesh.vertex_count();
  in.mesh.triangles = read_indices(faces, n, "triangle", 3);
  if (seams) in.seams = read_indices(*seams, n, "seam", 2);
  if (corner_keys) {
    in.keys = read_indices(*corner_keys, 0xffffffffu, "corner keys of face", 3);
    if (in.keys.size() != in.mesh.triangles.size())
      throw nb::value_error("corner_keys must be a (faces, 3) array: one key per face corner");
    in.has_keys = true;
  }
  return in;
}

} // namespace vrs_py
