#include "sketchlab/viewer/export_gltf.hpp"

#include <stdexcept>

#include <vtkGLTFExporter.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "scene_actors.hpp"
#include "sketchlab/viewer/camera.hpp"

namespace sketchlab::viewer {

std::string sketch_to_gltf(const Sketch& sketch, const SceneStyle& style) {
  vtkNew<vtkRenderer> renderer;
  add_sketch_actors(renderer, sketch, nullptr, style, curve_spacing(scene_bounds({&sketch}), style));
  // The exporter walks a window's renderers; the window is never shown or
  // rendered, so no display is opened.
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  vtkNew<vtkGLTFExporter> exporter;
  exporter->SetRenderWindow(window);
  exporter->InlineDataOn();
  exporter->SaveNormalOn();
  std::string gltf = exporter->WriteToString();
  if (gltf.empty()) throw std::runtime_error("glTF export: VTK wrote nothing");
  return gltf;
}

}  // namespace sketchlab::viewer
