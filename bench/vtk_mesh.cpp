#include "vtk_mesh.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>

namespace vrs_bench {

vtkSmartPointer<vtkPolyData> to_vtk(const vrs::Mesh& m) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(vtkIdType(m.vertex_count()));
  for (size_t v = 0; v < m.vertex_count(); ++v)
    points->SetPoint(vtkIdType(v), &m.positions[3 * v]);
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(vtkIdType(m.face_count()), vtkIdType(3 * m.face_count()));
  for (size_t f = 0; f < m.face_count(); ++f) {
    vtkIdType ids[3] = {m.triangles[3 * f], m.triangles[3 * f + 1], m.triangles[3 * f + 2]};
    cells->InsertNextCell(3, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(cells);
  return poly;
}

} // namespace vrs_bench
