#pragma once
// One display frame of controller input, in stage space (the tracking
// space, metres), as read from OpenXR or made up by tests.
#include <array>

#include "input_settings.hpp"
#include "sketchlab/plugin/controller_input.hpp"
#include "sketchlab/types.hpp"

namespace sketchlab::openxr {

using RigidPose = Pose;

struct HandFrame {
  bool tracked = false;
  RigidPose aim;      // the controller's aim pose (stage)
  bool grab = false;  // grab component held
};

struct ControllerFrame {
  double time = 0.0;       // seconds since the session started
  bool focused = true;     // input is only meaningful while the session has focus
  bool head_tracked = false;
  RigidPose head;          // stage
  std::array<HandFrame, 2> hands;  // indexed by Hand
  double draw_value = 0.0;         // draw button value in [0, 1]
  std::array<bool, command_count> buttons{};  // held this frame
};

}  // namespace sketchlab::openxr
