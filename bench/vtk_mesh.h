// The plain mesh as VTK polygonal data (for vtkDecimatePro and for the renders).
#pragma once

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "vrs/simplify.h"

namespace vrs_bench {

vtkSmartPointer<vtkPolyData> to_vtk(const vrs::Mesh& m);

} // namespace vrs_bench
