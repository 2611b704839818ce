// vrs_render: a mesh file to a PNG, flat shading with edges, offscreen through VTK's OpenGL
// renderer (run it under xvfb-run). Used for the report's side-by-side images.
//   vrs_render IN OUT.png [--azimuth DEG] [--elevation DEG] [--size W H]
#include <cstdio>
#include <cstdlib>
#include <string>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkWindowToImageFilter.h>

#include "mesh_io.h"
#include "vtk_mesh.h"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr,
                 "usage: vrs_render IN OUT.png [--azimuth A] [--elevation E] [--size W H]\n");
    return 2;
  }
  double azimuth = 0, elevation = 0;
  int width = 640, height = 480;
  for (int i = 3; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--azimuth" && i + 1 < argc)
      azimuth = std::atof(argv[++i]);
    else if (a == "--elevation" && i + 1 < argc)
      elevation = std::atof(argv[++i]);
    else if (a == "--size" && i + 2 < argc)
      width = std::atoi(argv[++i]), height = std::atoi(argv[++i]);
  }
  vrs_tool::LoadResult loaded = vrs_tool::load(argv[1]);
  if (!loaded.doc) {
    std::fprintf(stderr, "vrs_render: %s\n", loaded.error.c_str());
    return 1;
  }
  const vrs::Mesh m = vrs_tool::to_core(*loaded.doc);
  vrs_tool::close(loaded.doc);

  vtkSmartPointer<vtkPolyData> poly = vrs_bench::to_vtk(m);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetInterpolationToFlat();
  actor->GetProperty()->EdgeVisibilityOn();
  actor->GetProperty()->SetEdgeColor(0.15, 0.15, 0.2);
  actor->GetProperty()->SetColor(0.85, 0.82, 0.75);

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
