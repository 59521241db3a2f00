#pragma once
// What an application draws of the openxr input after a frame
// (ControllerState, sketchlab/plugin/controller_input.hpp): the hands, the
// placement, the mode and tool, the stroke in progress and the hand menu
// laid out as data, so the viewer needs none of this plugin's code.
#include "controller_frame.hpp"
#include "gesture_interpreter.hpp"
#include "sketchlab/plugin/controller_input.hpp"

namespace sketchlab::openxr {

// Whether the mode, tool or toggle `item` sets is on (undo, redo and
// next_stack act once: never).
bool menu_item_active(MenuItem item, const GestureInterpreter& input);

// The state after `frame` went through `input`; the menu only when
// settings.hand_menu.
ControllerState controller_state(const GestureInterpreter& input, const ControllerFrame& frame,
                                 const InputSettings& settings);

}  // namespace sketchlab::openxr
