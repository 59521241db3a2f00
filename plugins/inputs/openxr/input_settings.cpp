#include "input_settings.hpp"

#include <stdexcept>

namespace sketchlab::openxr {
namespace {

const char* const command_names[command_count] = {"undo",   "redo",      "mode",
                                                  "delete", "add_patch", "toggle_correction"};
const std::vector<std::string> components{"trigger", "squeeze", "select", "menu",      "a",
                                          "b",       "x",       "y",      "thumbstick", "trackpad"};

}  // namespace

std::string_view to_string(Command command) { return command_names[static_cast<std::size_t>(command)]; }

std::pair<Hand, std::string> parse_button(const std::string& button, const std::string& what) {
  const auto slash = button.find('/');
  const std::string hand = button.substr(0, slash);
  const std::string component = slash == std::string::npos ? "" : button.substr(slash + 1);
  bool known = false;
  for (const auto& c : components) known = known || c == component;
  if ((hand != "left" && hand != "right") || !known) {
    std::string list;
    for (const auto& c : components) list += (list.empty() ? "" : ", ") + c;
    throw std::invalid_argument(what + ": '" + button + "' is not <left|right>/<component> with component one of: " + list);
  }
  return {hand == "left" ? Hand::left : Hand::right, component};
}

std::vector<ParamSpec> input_param_specs() {
  const InputSettings d;
  std::vector<ParamSpec> specs{
      {"dominant_hand", ParamType::choice, std::string("right"), {}, {}, {"left", "right"}, "",
       "hand that draws, deletes and adds patches; zoom scales about it"},
      {"draw_button", ParamType::string, d.draw_button, {}, {}, {}, "",
       "float input drawn with; its value is the sample pressure"},
      {"grab_component", ParamType::choice, d.grab_component, {}, {}, {"squeeze", "select", "trigger"}, "",
       "component held on one hand to move the workspace, on both to zoom"},
      {"draw_threshold", ParamType::real, d.draw_threshold, 0.0, 1.0, {}, "",
       "trigger value at which a stroke starts and ends"},
      {"delete_radius", ParamType::real, d.delete_radius, 0.0, 1.0, {}, "m",
       "delete-nearest radius at zoom 1 (delta/s at zoom s)"},
      {"min_scale", ParamType::real, d.min_scale, 1e-3, 1.0, {}, "", "smallest workspace zoom"},
      {"max_scale", ParamType::real, d.max_scale, 1.0, 1e3, {}, "", "largest workspace zoom"},
      {"grab_rotates", ParamType::boolean, d.grab_rotates, {}, {}, {}, "",
       "one-hand grab turns the workspace with the hand (else translation only)"},
      {"initial_mode", ParamType::choice, std::string("auto"), {}, {},
       {"auto", "scaffold", "shape", "free"}, "", "drawing mode at the start"},
      {"headless_poll_hz", ParamType::real, d.headless_poll_hz, 1.0, 1000.0, {}, "Hz",
       "controller polls per second on its own (sketchlab record) when the runtime has no frame "
       "timing in headless sessions (Monado); time then comes from the runtime's clock"},
  };
  for (std::size_t i = 0; i < command_count; ++i)
    specs.push_back({std::string(command_names[i]) + "_button", ParamType::string, d.buttons[i], {}, {}, {}, "",
                     std::string("button for ") + command_names[i] + " (<left|right>/<component>)"});
  return specs;
}

InputSettings settings_from_params(const Params& p) {
  InputSettings s;
  s.dominant = p.string("dominant_hand") == "left" ? Hand::left : Hand::right;
  s.draw_button = p.string("draw_button");
  parse_button(s.draw_button, "draw_button");
  s.grab_component = p.string("grab_component");
  s.draw_threshold = p.real("draw_threshold");
  s.delete_radius = p.real("delete_radius");
  s.min_scale = p.real("min_scale");
  s.max_scale = p.real("max_scale");
  s.grab_rotates = p.boolean("grab_rotates");
  const std::string mode = p.string("initial_mode");
  s.initial_mode = mode == "auto" ? Layer::automatic : layer_from_string(mode);
  s.headless_poll_hz = p.real("headless_poll_hz");
  for (std::size_t i = 0; i < command_count; ++i) {
    const std::string name = std::string(command_names[i]) + "_button";
    s.buttons[i] = p.string(name);
    parse_button(s.buttons[i], name);
  }
  return s;
}

}  // namespace sketchlab::openxr
