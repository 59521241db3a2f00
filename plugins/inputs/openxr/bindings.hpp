#pragma once
// Suggested bindings of the openxr input's actions for the interaction
// profiles it supports (Khronos simple, Oculus Touch, Valve Index, HTC
// Vive). A button the settings name that a profile lacks falls back to the
// profile's own choice for that command when it has a free one; otherwise
// the command is unbound on that profile (README lists the result).
#include <string>
#include <vector>

#include "input_settings.hpp"

namespace sketchlab::openxr {

// Action names: "draw" (float), "grab" (boolean, per hand), "hand_pose"
// (pose, per hand) and one boolean per Command (to_string(command)).
struct Binding {
  std::string action;
  std::string path;  // "/user/hand/right/input/trigger/value"
  bool operator==(const Binding&) const = default;
};

struct ProfileBindings {
  std::string profile;  // "/interaction_profiles/oculus/touch_controller"
  std::vector<Binding> bindings;
};

// One entry per supported profile, in a fixed order; each input path is used
// by at most one action.
std::vector<ProfileBindings> suggested_bindings(const InputSettings& settings);

}  // namespace sketchlab::openxr
