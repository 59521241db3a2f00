#pragma once
// The VR scene: the desktop viewer's sketch actors (viewers/scene: raw
// strokes faint, curves, nodes, patches) placed in the stage by the
// workspace placement, plus what only VR has: the stroke being drawn, the
// controllers as small spheres in the current mode's colour (CASSIE), a
// grid of points near the dominant hand and the mirror plane, each when the
// workspace enables it.
#include <vector>

#include <vtkActor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "controller_frame.hpp"
#include "gesture_interpreter.hpp"
#include "scene_actors.hpp"
#include "sketchlab/sketch.hpp"

namespace sketchlab::vr {

// Colour of the controller spheres by drawing mode (correction off: paler).
viewer::Rgb mode_colour(Layer mode, bool correction);

class VrScene {
 public:
  VrScene(vtkRenderer* renderer, const viewer::SceneStyle& style);

  // Replaces the sketch actors (called when a newer snapshot is ready).
  void set_sketch(const Sketch& sketch);
  // Per frame: placement of the workspace, the stroke being drawn, the
  // controllers and the helpers.
  void update(const openxr::GestureInterpreter& input, const openxr::ControllerFrame& frame,
              openxr::Hand dominant);

 private:
  void apply_placement(const openxr::Placement& placement);
  vtkRenderer* renderer_;
  viewer::SceneStyle style_;
  viewer::SceneActors sketch_;
  vtkSmartPointer<vtkActor> stroke_, grid_, mirror_;
  vtkSmartPointer<vtkActor> hands_[2];
};

}  // namespace sketchlab::vr
