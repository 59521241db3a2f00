#include "controller_state.hpp"

namespace sketchlab::openxr {

bool menu_item_active(MenuItem item, const GestureInterpreter& input) {
  const bool drawing = input.tool() == Tool::draw;
  const MenuView& v = input.menu_view();
  switch (item) {
    case MenuItem::scaffold: return drawing && input.mode() == Layer::scaffold;
    case MenuItem::shape: return drawing && input.mode() == Layer::shape;
    case MenuItem::free: return drawing && input.mode() == Layer::free;
    case MenuItem::patch: return input.tool() == Tool::patch;
    case MenuItem::erase: return input.tool() == Tool::erase;
    case MenuItem::correction: return input.correction_enabled();
    case MenuItem::compare: return v.compare;
    case MenuItem::raw_strokes: return v.raw_strokes;
    case MenuItem::rejected: return v.rejected;
    case MenuItem::undo:
    case MenuItem::redo:
    case MenuItem::next_stack: return false;
  }
  return false;
}

ControllerState controller_state(const GestureInterpreter& input, const ControllerFrame& frame,
                                 const InputSettings& settings) {
  ControllerState s;
  const auto d = static_cast<std::size_t>(settings.dominant);
  s.pen = {frame.hands[d].tracked, frame.hands[d].aim};
  s.holder = {frame.hands[1 - d].tracked, frame.hands[1 - d].aim};
  s.placement = input.placement();
  s.workspace = input.workspace();
  s.mode = input.mode();
  s.correction = input.correction_enabled();
  s.tool = input.tool();
  s.stroke = input.stroke_in_progress();
  s.view = input.menu_view();
  if (settings.hand_menu) {
    // Laid out in the holding hand's aim frame (the identity pose).
    const RigidPose origin;
    const auto hover = input.menu_hover();
    for (std::size_t i = 0; i < menu_item_count; ++i) {
      const auto item = static_cast<MenuItem>(i);
      s.menu.items.push_back({std::string(menu_label(item)), menu_item_centre(origin, item),
                              menu_item_active(item, input), hover == item});
    }
    s.menu.cell = menu_cell;
    s.menu.centre = menu_centre(origin);
    s.menu.half_size = menu_half_size();
  }
  return s;
}

}  // namespace sketchlab::openxr
