// What the openxr input hands a viewer (ControllerState): the hands by role,
// the hand menu as data laid out as hand_menu.hpp lays it out, and the
// ControllerInput made through the plugin host, with its lifecycle errors.
#include <catch2/catch.hpp>

#include "controller_state.hpp"
#include "hand_menu.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "test_paths.hpp"

using namespace sketchlab;
using namespace sketchlab::openxr;

namespace {

ControllerFrame both_hands(double time, const Vec3& left, const Vec3& right, double trigger) {
  ControllerFrame f;
  f.time = time;
  f.hands[0].tracked = f.hands[1].tracked = true;
  f.hands[0].aim.position = left;
  f.hands[1].aim.position = right;
  f.draw_value = trigger;
  return f;
}

}  // namespace

TEST_CASE("the state gives the hands by role and the menu as the input lays it out", "[openxr]") {
  InputSettings settings;
  settings.hand_menu = true;
  settings.dominant = Hand::left;
  GestureInterpreter input(settings, Workspace{});
  // The left (dominant) hand's tip on the "shape" item of the menu the right
  // hand holds, trigger pulled: the mode becomes shape.
  const ControllerFrame f0 = both_hands(0.0, {0, 1.2, -0.5}, {0.3, 1.2, 0.0}, 0.0);
  input.step(f0);
  const Vec3 on_shape = menu_item_centre(f0.hands[1].aim, MenuItem::shape);
  input.step(both_hands(0.1, on_shape, {0.3, 1.2, 0.0}, 0.0));
  const ControllerFrame f2 = both_hands(0.2, on_shape, {0.3, 1.2, 0.0}, 0.9);
  input.step(f2);
  const ControllerState s = controller_state(input, f2, settings);
  CHECK(s.pen.aim.position == on_shape);
  CHECK(s.holder.aim.position == Vec3(0.3, 1.2, 0.0));
  CHECK(s.mode == Layer::shape);
  CHECK(s.tool == ControllerTool::draw);
  CHECK(s.stroke.empty());  // a menu pick draws nothing
  REQUIRE(s.menu.items.size() == menu_item_count);
  CHECK(s.menu.cell == menu_cell);
  CHECK(s.menu.centre == menu_centre(RigidPose{}));
  CHECK(s.menu.half_size == menu_half_size());
  for (std::size_t i = 0; i < menu_item_count; ++i) {
    const auto item = static_cast<MenuItem>(i);
    INFO(menu_label(item));
    CHECK(s.menu.items[i].label == menu_label(item));
    CHECK(s.menu.items[i].centre == menu_item_centre(RigidPose{}, item));
    CHECK(s.menu.items[i].hovered == (item == MenuItem::shape));
    CHECK(s.menu.items[i].active ==
          (item == MenuItem::shape || item == MenuItem::correction || item == MenuItem::raw_strokes));
  }
  // Without the menu (a headless recording), none is described.
  InputSettings plain;
  GestureInterpreter headless(plain, Workspace{});
  headless.step(f0);
  CHECK(controller_state(headless, f0, plain).menu.items.empty());
}

#ifdef SKETCHLAB_TEST_XR_RUNTIME_JSON
TEST_CASE("a viewer gets the openxr input as a ControllerInput through the plugin host", "[openxr][plugin]") {
  PluginHost host;
  host.load_directories({SKETCHLAB_BUILD_PLUGIN_DIR});
  CHECK(host.controller_input_names() == std::vector<std::string>{"openxr"});
  CHECK_THROWS_WITH(host.make_controller_input("replay", {}),
                    "input 'replay' is not a controller input; controller inputs: openxr");
  CHECK_THROWS_AS(host.make_controller_input("openxr", {{"draw_threshold", 7.0}}), ParamError);
  const std::shared_ptr<ControllerInput> input = host.make_controller_input("openxr", {});
  CHECK(input->header().source.at("input") == "openxr");
  CHECK(input->next().state() == NextEvent::State::not_ready);
  CHECK(input->state().menu.items.empty());  // nothing before attach
  // Out of order: the call's error, and the input ends.
  input->read_frame(0, 0.0, true);
  CHECK(input->error() == "openxr input: read_frame before attach");
  CHECK(input->next().is_ended());
}
#endif
