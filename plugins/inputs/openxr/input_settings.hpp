#pragma once
// What the openxr input's parameters say: which button does what and the
// thresholds of the gestures. Buttons are named "<hand>/<component>", e.g.
// "left/x", "right/trigger" (components: trigger, squeeze, select, menu,
// a, b, x, y, thumbstick, trackpad); bindings.hpp maps them onto each
// interaction profile.
#include <array>
#include <string>
#include <vector>

#include "sketchlab/plugin/params.hpp"
#include "sketchlab/stroke.hpp"

namespace sketchlab::openxr {

enum class Hand { left = 0, right = 1 };

// Discrete commands, each on a button (rising edge).
enum class Command { undo, redo, mode, delete_nearest, add_patch, toggle_correction };
inline constexpr std::size_t command_count = 6;
std::string_view to_string(Command command);

struct InputSettings {
  Hand dominant = Hand::right;
  std::string draw_button = "right/trigger";  // float: its value is the pressure
  std::string grab_component = "squeeze";     // on both hands
  std::array<std::string, command_count> buttons{"left/x",     "left/y",          "right/a",
                                                 "right/b",    "right/thumbstick", "left/menu"};
  double draw_threshold = 0.1;   // trigger value that starts and ends a stroke
  double delete_radius = 0.05;   // m at zoom 1 (δ/s at zoom s)
  double min_scale = 0.05, max_scale = 20.0;
  bool grab_rotates = true;      // one-hand grab moves and turns the workspace
  Layer initial_mode = Layer::automatic;
  // The hand menu (hand_menu.hpp) is picked with the draw trigger. Not a
  // parameter: the VR viewer, which draws the menu, turns it on; a headless
  // recording shows nothing to pick.
  bool hand_menu = false;
  // Controller polls per second of a headless session on a runtime without
  // frame timing there (Monado's XR_MND_headless), paced by the input itself.
  double headless_poll_hz = 90.0;
};

std::vector<ParamSpec> input_param_specs();
// `params` already validated against input_param_specs(). Throws
// std::invalid_argument naming the parameter for a malformed button name.
InputSettings settings_from_params(const Params& params);

// "left/x" -> {Hand::left, "x"}; throws std::invalid_argument naming `what`.
std::pair<Hand, std::string> parse_button(const std::string& button, const std::string& what);

}  // namespace sketchlab::openxr
