#include <chrono>

#include <vtkCellArray.h>
#include <vtkDecimatePro.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include "peers.h"
#include "vtk_mesh.h"

namespace vrs_bench {

namespace {

// max_error < 0: no error limit.
PeerResult decimate(const vrs::Mesh& in, size_t target_faces, double max_error) {
  vtkSmartPointer<vtkPolyData> poly = to_vtk(in);

  vtkNew<vtkDecimatePro> deci;
  deci->SetInputData(poly);
  deci->SetTargetReduction(1.0 -
                           double(target_faces) / double(std::max<size_t>(1, in.face_count())));
  deci->PreserveTopologyOn(); // no splits, no holes: like ours, a subset of the vertices
  if (max_error >= 0) {
    deci->SetErrorIsAbsolute(1);
    deci->AccumulateErrorOn(); // "a global bound on mesh error", as VTK documents it
    deci->SetAbsoluteError(max_error);
  }
  PeerResult r;
  MemoryProbe probe;
  const auto t0 = std::chrono::steady_clock::now();
  deci->Update();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  probe.finish(r);

  vtkPolyData* out = deci->GetOutput();
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p) {
    double x[3];
    out->GetPoint(p, x);
    r.mesh.positions.insert(r.mesh.positions.end(), {float(x[0]), float(x[1]), float(x[2])});
  }
  vtkCellArray* polys = out->GetPolys();
  vtkNew<vtkIdList> ids;
  for (polys->InitTraversal(); polys->GetNextCell(ids);)
    if (ids->GetNumberOfIds() == 3)
      for (int k = 0; k < 3; ++k)
        r.mesh.triangles.push_back(uint32_t(ids->GetId(k)));
  if (r.mesh.face_count() > target_faces + target_faces / 100) r.note = "target not reached";
  return r;
}

} // namespace

PeerResult run_vtk(const vrs::Mesh& in, size_t target_faces) {
  return decimate(in, target_faces, -1);
}

PeerResult run_vtk_bound(const vrs::Mesh& in, double max_error) {
  PeerResult r = decimate(in, 0, max_error);
  r.note.clear();
  return r;
}

} // namespace vrs_bench
