#pragma once
// What the user holds (issue #25): a pen-shaped controller per hand, the brush tip
// at the dominant hand's aim point in the colour of the current mode or tool
// (paler with correction off), a label on the dominant hand naming the mode
// and whether correction is on, and on the other hand the input's menu
// (ControllerState::menu, laid out by the input: active items lit, the
// hovered one highlighted), the shown stack's name and a scale bar that
// follows the zoom.
#include <array>
#include <string>
#include <vector>

#include <vtkActor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include "sketchlab/plugin/controller_input.hpp"
#include "sketchlab/viewer/scene_style.hpp"

namespace sketchlab::vr {

inline constexpr double brush_tip_radius = 0.006;  // m, stage
inline constexpr viewer::Rgb menu_item_colour{0.90, 0.91, 0.93};
inline constexpr viewer::Rgb menu_active_colour{0.25, 0.55, 0.95};
inline constexpr viewer::Rgb menu_hover_colour{1.00, 0.78, 0.20};
inline constexpr viewer::Rgb erase_colour{0.90, 0.20, 0.20};

// Brush-tip colour by drawing mode (correction off: paler): CASSIE §3 tells
// the controllers apart by colour.
viewer::Rgb mode_colour(Layer mode, bool correction);
// The brush tip's colour for the input's mode, tool and correction.
viewer::Rgb tip_colour(const ControllerState& input, const viewer::SceneStyle& style);
// The mode label of the dominant hand, e.g. "shape" or "scaffold, correction off".
std::string mode_label(const ControllerState& input);
// The scale bar: the shortest round workspace length (1, 2 or 5 times a
// power of ten, metres) at least 3 cm long on the stage at zoom `scale` (so
// under 7.5 cm, the menu's width), and its label ("5 cm").
std::pair<double, std::string> scale_bar(double scale);

class HandActors {
 public:
  HandActors(vtkRenderer* renderer, const viewer::SceneStyle& style, std::vector<std::string> stack_names);
  void update(const ControllerState& input);

 private:
  // Builds the menu's squares and labels when its items changed.
  void set_menu(const ControllerMenu& menu);
  void set_text(vtkActor* actor, std::string& shown, const std::string& text, double height, const Vec3& origin,
                bool centred);
  viewer::SceneStyle style_;
  std::vector<std::string> stack_names_;
  std::array<vtkSmartPointer<vtkActor>, 2> bodies_;
  vtkSmartPointer<vtkActor> tip_, mode_label_;
  vtkSmartPointer<vtkActor> menu_, menu_labels_, stack_label_, scale_bar_, scale_label_;
  vtkSmartPointer<vtkUnsignedCharArray> menu_colours_;
  std::vector<std::string> menu_shown_;  // labels of the menu the actors hold
  std::string mode_text_, stack_text_, scale_text_;
  double bar_length_ = -1.0;
};

}  // namespace sketchlab::vr
