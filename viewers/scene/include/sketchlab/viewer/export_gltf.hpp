#pragma once
// A sketch as a glTF 2.0 document, drawn as the offscreen renderer draws it
// (scene_style.hpp: raw strokes, curves per layer, nodes, patches), written
// by VTK's vtkGLTFExporter with the buffers inline (base64), so one JSON
// text holds the whole scene: the report's interactive 3D views load it
// (lab/report_web/), and Blender, three.js editors or any glTF viewer open
// the case's scene.gltf. Lengths in metres. Needs no display (nothing is
// rendered). Throws std::runtime_error when VTK writes nothing.
#include <string>

#include "sketchlab/sketch.hpp"
#include "sketchlab/viewer/scene_style.hpp"

namespace sketchlab::viewer {

std::string sketch_to_gltf(const Sketch& sketch, const SceneStyle& style = {});

}  // namespace sketchlab::viewer
