#pragma once
// The place the user draws in (issue #25): a ground disc to the horizon and
// a floor grid in the stage (fixed, they orient the user), plus, in the
// workspace (they move with grab and zoom), the workspace grid's points
// around the dominant hand and the mirror plane, each when the workspace
// enables it.
#include <vtkActor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "sketchlab/plugin/controller_input.hpp"
#include "sketchlab/viewer/scene_style.hpp"

namespace sketchlab::vr {

// Colours of the stage (linear RGB): the sky is the renderer's background.
inline constexpr viewer::Rgb sky_colour{0.80, 0.86, 0.93};
inline constexpr viewer::Rgb ground_colour{0.62, 0.64, 0.66};
inline constexpr viewer::Rgb floor_line_colour{0.40, 0.42, 0.46};
inline constexpr double floor_grid_spacing = 0.5;  // m, stage
inline constexpr double floor_grid_extent = 5.0;   // m from the stage origin
inline constexpr double ground_radius = 40.0;      // m: its rim is the horizon (far clip is 100 m)

class WorkspaceActors {
 public:
  WorkspaceActors(vtkRenderer* renderer, const viewer::SceneStyle& style);
  // Per frame: workspace placement and what the workspace enables.
  void update(const ControllerState& input);

 private:
  vtkSmartPointer<vtkActor> ground_, floor_grid_, grid_points_, mirror_;
};

}  // namespace sketchlab::vr
