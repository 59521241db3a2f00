#include "input_settings.hpp"

#include <stdexcept>

#include "sketchlab/plugin/param_table.hpp"

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

namespace {

const ParamTable<InputSettings>& parameters() {
  using S = InputSettings;
  static const auto table = [] {
    ParamTable<S> t;
    t.choice("dominant_hand", &S::dominant,
             std::vector<std::pair<std::string, Hand>>{{"left", Hand::left}, {"right", Hand::right}},
             "hand that draws, deletes and adds patches; zoom scales about it")
        .string("draw_button", &S::draw_button, "float input drawn with; its value is the sample pressure")
        .choice("grab_component", &S::grab_component, std::vector<std::string>{"squeeze", "select", "trigger"},
                "component held on one hand to move the workspace, on both to zoom")
        .real("draw_threshold", &S::draw_threshold, 0.0, 1.0, "", "trigger value at which a stroke starts and ends")
        .real("delete_radius", &S::delete_radius, 0.0, 1.0, "m",
              "delete-nearest radius at zoom 1 (delta/s at zoom s)")
        .real("min_scale", &S::min_scale, 1e-3, 1.0, "", "smallest workspace zoom")
        .real("max_scale", &S::max_scale, 1.0, 1e3, "", "largest workspace zoom")
        .boolean("grab_rotates", &S::grab_rotates,
                 "one-hand grab turns the workspace with the hand (else translation only)")
        .choice("initial_mode", &S::initial_mode,
                std::vector<std::pair<std::string, Layer>>{{"auto", Layer::automatic},
                                                           {"scaffold", Layer::scaffold},
                                                           {"shape", Layer::shape},
                                                           {"free", Layer::free}},
                "drawing mode at the start")
        .real("headless_poll_hz", &S::headless_poll_hz, 1.0, 1000.0, "Hz",
              "controller polls per second on its own (sketchlab record) when the runtime has no frame "
              "timing in headless sessions (Monado); time then comes from the runtime's clock");
    for (std::size_t i = 0; i < command_count; ++i)
      t.string(std::string(command_names[i]) + "_button", [i](S& s) -> std::string& { return s.buttons[i]; },
               std::string("button for ") + command_names[i] + " (<left|right>/<component>)");
    t.check([](S& s) {
      parse_button(s.draw_button, "draw_button");
      for (std::size_t i = 0; i < command_count; ++i)
        parse_button(s.buttons[i], std::string(command_names[i]) + "_button");
    });
    return t;
  }();
  return table;
}

}  // namespace

std::vector<ParamSpec> input_param_specs() { return parameters().specs(); }

InputSettings settings_from_params(const Params& p) { return parameters().read(p); }

}  // namespace sketchlab::openxr
