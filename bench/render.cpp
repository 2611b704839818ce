// vrs_render: a mesh file to a PNG, flat shading with edges, offscreen through VTK's OpenGL
// renderer (run it under xvfb-run). Used for the report's side-by-side images. With --texture
// a mesh with per-corner texture coordinates is drawn with a checkerboard texture (one square
// per 1/8 of texture space), so a texture torn by the simplification shows.
//   vrs_render IN OUT.png [--azimuth DEG] [--elevation DEG] [--size W H] [--texture]
#include <cstdio>
#include <cstdlib>
#include <string>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>
#include <vtkWindowToImageFilter.h>

#include "mesh_io.h"
#include "vcg_mesh.h"
#include "vtk_mesh.h"

namespace {

// Three points a face, each with its corner's texture coordinate.
vtkSmartPointer<vtkPolyData> textured_polydata(const vrs_tool::VcgMesh& m) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> uv;
  uv->SetNumberOfComponents(2);
  vtkNew<vtkCellArray> cells;
  for (const auto& f : m.face) {
    if (f.IsD()) continue;
    vtkIdType ids[3];
    for (int c = 0; c < 3; ++c) {
      const auto& p = f.cV(c)->cP();
      ids[c] = points->InsertNextPoint(p[0], p[1], p[2]);
      uv->InsertNextTuple2(f.cWT(c).U(), f.cWT(c).V());
    }
    cells->InsertNextCell(3, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(cells);
  poly->GetPointData()->SetTCoords(uv);
  return poly;
}

vtkSmartPointer<vtkTexture> checkerboard() {
  vtkNew<vtkImageData> image;
  const int n = 256;
  image->SetDimensions(n, n, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      auto* px = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
      bool dark = ((x / 32) + (y / 32)) % 2;
      px[0] = dark ? 40 : 235;
      px[1] = dark ? 90 : 200;
      px[2] = dark ? 160 : 120;
    }
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->RepeatOn();
  texture->InterpolateOff();
  return texture;
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr,
                 "usage: vrs_render IN OUT.png [--azimuth A] [--elevation E] [--size W H]\n");
    return 2;
  }
  double azimuth = 0, elevation = 0;
  bool textured = false;
  int width = 640, height = 480;
  for (int i = 3; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--azimuth" && i + 1 < argc)
      azimuth = std::atof(argv[++i]);
    else if (a == "--elevation" && i + 1 < argc)
      elevation = std::atof(argv[++i]);
    else if (a == "--size" && i + 2 < argc)
      width = std::atoi(argv[++i]), height = std::atoi(argv[++i]);
    else if (a == "--texture")
      textured = true;
  }
  vrs_tool::LoadResult loaded = vrs_tool::load(argv[1]);
  if (!loaded.doc) {
    std::fprintf(stderr, "vrs_render: %s\n", loaded.error.c_str());
    return 1;
  }
  textured = textured && loaded.doc->corner_data().texcoord;
  vtkSmartPointer<vtkPolyData> poly = textured ? textured_polydata(loaded.doc->mesh)
                                               : vrs_bench::to_vtk(vrs_tool::to_core(*loaded.doc));
  vrs_tool::close(loaded.doc);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetInterpolationToFlat();
  actor->GetProperty()->EdgeVisibilityOn();
  actor->GetProperty()->SetEdgeColor(0.15, 0.15, 0.2);
  actor->GetProperty()->SetColor(0.85, 0.82, 0.75);
  if (textured) {
    actor->SetTexture(checkerboard());
    actor->GetProperty()->SetColor(1, 1, 1);
    actor->GetProperty()->EdgeVisibilityOff();
  }

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(1, 1, 1);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(azimuth);
  renderer->GetActiveCamera()->Elevation(elevation);
  renderer->GetActiveCamera()->OrthogonalizeViewUp();
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(1.3);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(width, height);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(argv[2]);
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  return 0;
}
