// The simplifiers compared, each called the way its own users call it, on the same plain mesh
// and target face count. `seconds` times the simplification call only (not conversion or I/O).
#pragma once

#include <string>

#include "vrs/simplify.h"

namespace vrs_bench {

struct PeerResult {
  vrs::Mesh mesh;
  double seconds = 0;
  double peak_mb = 0;     // resident memory high-water mark during the timed call, whole process
  double extra_mb = 0;    // that peak minus the resident memory just before the call
  std::string note;       // why a target was missed
  double error_bound = 0; // ours with a tracked bound: the certified Hausdorff bound (mesh units)
};

// Brackets the timed call: resets the kernel's high-water mark (Linux clear_refs), and reads it
// back afterwards into the result. Costs nothing inside the call.
class MemoryProbe {
 public:
  MemoryProbe();
  void finish(PeerResult& r) const;

 private:
  double before_mb_ = 0;
};

// vrsimplify with `options` (its target is replaced by the face count).
PeerResult run_ours(const vrs::Mesh& in, size_t target_faces, vrs::Options options);
// Ours on `m` in place, with what the run would take on 8 and 16 threads (the run's own
// measure of its loops' chunks; see vrs_bench --serial).
vrs::Report run_ours_projected(vrs::Mesh& m, const vrs::Options& options, double& seconds_8,
                               double& seconds_16);
// MeshLab's Quadric Edge Collapse Decimation: vcglib's TriEdgeCollapseQuadric with the filter's
// dialog defaults and its post-simplification cleaning (filter_meshing 2020.09).
// `preserve_topology`: the dialog's "Preserve Topology" (off by default), which refuses the
// collapses that would change the genus, as ours never does. `optimal_placement` off (the
// dialog's "Optimal position of simplified vertices"): each collapse moves one end onto the
// other, so the output keeps a subset of the input vertices, as ours.
PeerResult run_qecd(const vrs::Mesh& in, size_t target_faces, bool preserve_topology = false,
                    bool optimal_placement = true);
// meshoptimizer's meshopt_simplify (keeps a subset of the vertices), no error limit.
PeerResult run_meshopt(const vrs::Mesh& in, size_t target_faces);
// OpenMesh's decimater with its quadric module as the priority (half-edge collapses, so the
// output keeps a subset of the input vertices), as OpenMesh's own examples set it up.
PeerResult run_openmesh(const vrs::Mesh& in, size_t target_faces);
// The same three with an error limit instead of a face count (`--bound` of vrs_bench), each in
// its own terms: ours a certified symmetric Hausdorff bound (mesh units), meshoptimizer its
// `target_error` (relative to the mesh's extent; meshopt_simplifyScale), vtkDecimatePro its
// absolute MaximumError (distance to the average plane, accumulated).
PeerResult run_ours_bound(const vrs::Mesh& in, double max_error, vrs::Options options);
PeerResult run_meshopt_bound(const vrs::Mesh& in, double max_error);
PeerResult run_vtk_bound(const vrs::Mesh& in, double max_error);
// VTK's vtkDecimatePro (Schroeder's vertex removal) with PreserveTopology on, as ours.
PeerResult run_vtk(const vrs::Mesh& in, size_t target_faces);

} // namespace vrs_bench
