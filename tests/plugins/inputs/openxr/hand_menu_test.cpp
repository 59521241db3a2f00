// The hand menu: its layout, the hit test, and what picking each item does
// through the gesture interpreter (events recorded, view state, tools).
#include <catch2/catch.hpp>

#include <cmath>

#include "gesture_interpreter.hpp"
#include "hand_menu.hpp"
#include "sketchlab/recording/event_json.hpp"

using namespace sketchlab;
using namespace sketchlab::openxr;

namespace {

constexpr double frame_dt = 1.0 / 90.0;

InputSettings with_menu() {
  InputSettings s;
  s.hand_menu = true;
  return s;
}

RigidPose left_hand() {
  RigidPose p;
  p.position = {-0.3, 1.2, 0.0};
  // Turned 30° about y and tilted 20° about x: the layout follows the hand.
  p.orientation = (Eigen::AngleAxisd(0.5236, Vec3::UnitY()) * Eigen::AngleAxisd(-0.35, Vec3::UnitX())).normalized();
  return p;
}

ControllerFrame menu_frame(int frame, const Vec3& tip, double trigger) {
  ControllerFrame f;
  f.time = frame * frame_dt;
  f.hands[0].tracked = true;
  f.hands[0].aim = left_hand();
  f.hands[1].tracked = true;
  f.hands[1].aim.position = tip;
  f.draw_value = trigger;
  return f;
}

// Presses and releases the trigger with the tip on `item`; returns the events.
std::vector<Event> pick(GestureInterpreter& g, int& frame, MenuItem item) {
  const Vec3 tip = menu_item_centre(left_hand(), item);
  std::vector<Event> all;
  for (double trigger : {0.0, 0.9, 0.9, 0.9, 0.0})
    for (auto& e : g.step(menu_frame(frame++, tip, trigger))) all.push_back(std::move(e));
  return all;
}

}  // namespace

TEST_CASE("every menu item is found at its own centre, and nothing off the panel", "[openxr]") {
  const RigidPose hand = left_hand();
  for (std::size_t i = 0; i < menu_item_count; ++i) {
    const auto item = static_cast<MenuItem>(i);
    const Vec3 c = menu_item_centre(hand, item);
    CHECK(menu_item_at(hand, c) == item);
    // A touch slightly off centre and off the plane still picks it.
    CHECK(menu_item_at(hand, c + hand.orientation * Vec3(0.4 * menu_cell, -0.4 * menu_cell, 0.4 * menu_cell)) == item);
    CHECK_FALSE(menu_item_at(hand, c + hand.orientation * Vec3(0, 0, 0.6 * menu_cell)).has_value());
    CHECK_FALSE(menu_label(item).empty());
  }
  // Neighbouring items are one cell apart.
  CHECK((menu_item_centre(hand, MenuItem::shape) - menu_item_centre(hand, MenuItem::scaffold)).norm() ==
        Approx(menu_cell));
  CHECK_FALSE(menu_item_at(hand, hand.position).has_value());  // the controller itself is not on the menu
  CHECK_FALSE(menu_item_at(hand, menu_centre(hand) + hand.orientation * Vec3(menu_half_size().x() + 0.001, 0, 0)));
  CHECK_FALSE(menu_item_at(hand, Vec3(NAN, 0, 0)).has_value());
}

TEST_CASE("picking menu items records the commands and sets the tool and view", "[openxr]") {
  GestureInterpreter g(with_menu(), Workspace{});
  g.set_stack_count(2);
  int frame = 0;
  // Hovering highlights without a press.
  g.step(menu_frame(frame++, menu_item_centre(left_hand(), MenuItem::undo), 0.0));
  CHECK(g.menu_hover() == MenuItem::undo);

  auto events = pick(g, frame, MenuItem::shape);
  REQUIRE(events.size() == 1);
  CHECK(std::get<ModeEvent>(events[0].payload).mode == Layer::shape);
  CHECK(g.mode() == Layer::shape);
  CHECK(pick(g, frame, MenuItem::shape).empty());  // already in that mode: nothing to record

  events = pick(g, frame, MenuItem::correction);
  REQUIRE(events.size() == 1);
  CHECK_FALSE(std::get<CorrectionEvent>(events[0].payload).enabled);
  CHECK_FALSE(g.correction_enabled());
  CHECK(std::holds_alternative<UndoEvent>(pick(g, frame, MenuItem::undo).at(0).payload));
  CHECK(std::holds_alternative<RedoEvent>(pick(g, frame, MenuItem::redo).at(0).payload));

  CHECK(pick(g, frame, MenuItem::next_stack).empty());  // view state, not recorded
  CHECK(g.menu_view().stack == 1);
  pick(g, frame, MenuItem::next_stack);
  CHECK(g.menu_view().stack == 0);
  pick(g, frame, MenuItem::compare);
  CHECK(g.menu_view().compare);
  pick(g, frame, MenuItem::raw_strokes);
  CHECK_FALSE(g.menu_view().raw_strokes);
  pick(g, frame, MenuItem::rejected);
  CHECK(g.menu_view().rejected);

  // A press on the menu never starts a stroke, even when the tip then
  // leaves the menu with the trigger held.
  const Vec3 tip = menu_item_centre(left_hand(), MenuItem::raw_strokes);
  g.step(menu_frame(frame++, tip, 0.9));
  for (int k = 1; k <= 10; ++k) CHECK(g.step(menu_frame(frame++, Vec3(0.1 * k, 1.5, 0.0), 0.9)).empty());
  CHECK(g.stroke_in_progress().empty());
  CHECK(g.step(menu_frame(frame++, Vec3(1.0, 1.5, 0.0), 0.0)).empty());
}

TEST_CASE("compare needs two stacks", "[openxr]") {
  GestureInterpreter g(with_menu(), Workspace{});
  int frame = 0;
  pick(g, frame, MenuItem::compare);
  CHECK_FALSE(g.menu_view().compare);
  pick(g, frame, MenuItem::next_stack);
  CHECK(g.menu_view().stack == 0);
}

TEST_CASE("the patch and erase tools act once per trigger press at the tip", "[openxr]") {
  const InputSettings settings = with_menu();
  GestureInterpreter g(settings, Workspace{});
  int frame = 0;
  pick(g, frame, MenuItem::patch);
  CHECK(g.tool() == Tool::patch);
  const Vec3 p(0.2, 1.5, -0.1);
  std::vector<Event> events;
  for (double trigger : {0.0, 0.8, 0.8, 0.8, 0.0})
    for (auto& e : g.step(menu_frame(frame++, p, trigger))) events.push_back(std::move(e));
  REQUIRE(events.size() == 1);
  CHECK((std::get<AddPatchEvent>(events[0].payload).point - p).norm() < 1e-12);

  pick(g, frame, MenuItem::erase);
  CHECK(g.tool() == Tool::erase);
  events.clear();
  for (double trigger : {0.0, 0.8, 0.0})
    for (auto& e : g.step(menu_frame(frame++, p, trigger))) events.push_back(std::move(e));
  REQUIRE(events.size() == 1);
  const auto& del = std::get<DeleteNearEvent>(events[0].payload);
  CHECK((del.point - p).norm() < 1e-12);
  CHECK(del.radius == Approx(settings.delete_radius));
  CHECK(g.stroke_in_progress().empty());

  pick(g, frame, MenuItem::erase);  // picking the tool again puts the pen back
  CHECK(g.tool() == Tool::draw);
  pick(g, frame, MenuItem::patch);
  pick(g, frame, MenuItem::free);  // a mode puts the pen back too
  CHECK(g.tool() == Tool::draw);
  CHECK(g.mode() == Layer::free);
}

TEST_CASE("without the hand menu (headless recording) a press there is a stroke", "[openxr]") {
  GestureInterpreter g(InputSettings{}, Workspace{});
  int frame = 0;
  const Vec3 tip = menu_item_centre(left_hand(), MenuItem::undo);
  g.step(menu_frame(frame++, tip, 0.9));
  CHECK_FALSE(g.menu_hover().has_value());
  g.step(menu_frame(frame++, tip + Vec3(0.05, 0, 0), 0.9));
  const auto events = g.step(menu_frame(frame++, tip, 0.0));
  REQUIRE(events.size() == 1);
  CHECK(std::holds_alternative<StrokeEvent>(events[0].payload));
}

TEST_CASE("a trigger held across a focus loss picks nothing when focus returns", "[openxr]") {
  GestureInterpreter g(with_menu(), Workspace{});
  int frame = 0;
  const Vec3 tip = menu_item_centre(left_hand(), MenuItem::undo);
  g.step(menu_frame(frame++, tip, 0.9));  // pressed on the menu: undo
  ControllerFrame lost = menu_frame(frame++, tip, 0.9);
  lost.focused = false;
  g.step(lost);
  CHECK(g.step(menu_frame(frame++, tip, 0.9)).empty());
}
