#include "mesh/input_check.h"

#include <cmath>
#include <cstdint>

#include "mesh/spatial_order.h"
#include "mesh/topology.h"

namespace vrs {

std::string check_options(const Options& o, size_t vertex_count, size_t face_count) {
  const Target& t = o.target;
  if (static_cast<unsigned>(t.kind) > static_cast<unsigned>(TargetKind::Auto))
    return "unknown target kind";
  if (t.kind == TargetKind::Ratio && !(t.ratio >= 0.0 && t.ratio <= 1.0))
    return "ratio must be in [0, 1], got " + std::to_string(t.ratio);
  if (t.kind == TargetKind::MaxFactor && !(t.max_factor >= 0.0 && std::isfinite(t.max_factor)))
    return "max factor must be finite and >= 0, got " + std::to_string(t.max_factor);
  if (static_cast<unsigned>(o.mode) > static_cast<unsigned>(Mode::Planar2D)) return "unknown mode";
  if (static_cast<unsigned>(o.tuning.queue) > static_cast<unsigned>(QueueKind::Heap))
    return "unknown queue";
  if (static_cast<unsigned>(o.tuning.mapping) > static_cast<unsigned>(IntervalMapping::Logarithmic))
    return "unknown interval mapping";
  if (o.threads < 0 || o.threads > 1024)
    return "threads must be in [0, 1024] (0: every core this process may use), got " +
           std::to_string(o.threads);
  if (o.tuning.part_vertices < 0 || (o.tuning.part_vertices > 0 && o.tuning.part_vertices < 64))
    return "part vertices must be 0 (no parts) or >= 64, got " +
           std::to_string(o.tuning.part_vertices);
  if (o.tuning.intervals < 2 || o.tuning.intervals > (1 << 20))
    return "intervals must be in [2, 1048576], got " + std::to_string(o.tuning.intervals);
  if (!(o.max_normal_angle_deg > 0.0 && o.max_normal_angle_deg <= 90.0))
    return "max normal angle must be in (0, 90] degrees, got " +
           std::to_string(o.max_normal_angle_deg);
  if (o.max_valence < 3 || o.max_valence > kMaxRing)
    return "max valence must be in [3, " + std::to_string(kMaxRing) + "], got " +
           std::to_string(o.max_valence);
  if (o.locked && o.locked->size() != vertex_count)
    return "lock array has " + std::to_string(o.locked->size()) + " entries for " +
           std::to_string(vertex_count) + " vertices";
  if (o.polygon_faces && o.polygon_faces->size() != face_count)
    return "polygon face array has " + std::to_string(o.polygon_faces->size()) + " entries for " +
           std::to_string(face_count) + " faces";
  if (!(o.feature_angle_deg >= 0.0 && o.feature_angle_deg <= 180.0))
    return "feature angle must be in [0, 180] degrees, got " + std::to_string(o.feature_angle_deg);
  if (!(o.max_error >= 0.0)) return "max error must be >= 0, got " + std::to_string(o.max_error);
  if (o.constrained_edges) {
    const auto& e = *o.constrained_edges;
    if (e.size() % 2) return "constrained edges must be vertex pairs (an even count)";
    for (size_t i = 0; i < e.size(); ++i)
      if (e[i] >= vertex_count)
        return "constrained edge " + std::to_string(i / 2) + " has vertex index " +
               std::to_string(e[i]) + ", out of range for " + std::to_string(vertex_count) +
               " vertices";
  }
  return {};
}

std::string check_mesh(const Mesh& m) {
  if (m.positions.size() % 3 != 0) return "positions size is not a multiple of 3";
  if (m.triangles.size() % 3 != 0) return "triangles size is not a multiple of 3";
  // Nothing to simplify is a mistake upstream (an empty file, a point cloud), not a result.
  if (m.triangles.empty()) return "the mesh has no faces";
  const size_t n = m.vertex_count();
  if (n >= kNone) return "too many vertices (" + std::to_string(n) + ")";
  if (m.triangles.size() / 3 >= kRewrittenSlot)
    return "too many triangles (" + std::to_string(m.triangles.size() / 3) + "; at most 2^31 - 1)";
  for (size_t i = 0; i < m.triangles.size(); ++i)
    if (m.triangles[i] >= n)
      return "triangle " + std::to_string(i / 3) + " has vertex index " +
             std::to_string(m.triangles[i]) + ", out of range for " + std::to_string(n) +
             " vertices";
  return {};
}

} // namespace vrs
