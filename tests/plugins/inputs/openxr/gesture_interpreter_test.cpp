// The openxr input's gestures on made-up controller frames.
#include <catch2/catch.hpp>

#include "gesture_interpreter.hpp"
#include "sketchlab/recording/event_json.hpp"

using namespace sketchlab;
using namespace sketchlab::openxr;

namespace {

constexpr double dt = 1.0 / 90.0;

ControllerFrame at(int frame, const Vec3& right, double trigger = 0.0) {
  ControllerFrame f;
  f.time = frame * dt;
  f.head_tracked = true;
  f.head.position = {0, 1.6, 0.5};
  f.hands[1].tracked = true;
  f.hands[1].aim.position = right;
  f.hands[0].tracked = true;
  f.hands[0].aim.position = {-0.3, 1.2, 0.0};
  f.draw_value = trigger;
  return f;
}

std::vector<Event> run(GestureInterpreter& g, const std::vector<ControllerFrame>& frames) {
  std::vector<Event> all;
  for (const auto& f : frames)
    for (auto& e : g.step(f)) all.push_back(std::move(e));
  return all;
}

}  // namespace

TEST_CASE("drawing with the trigger makes one stroke with the trigger value as pressure", "[openxr]") {
  GestureInterpreter g(InputSettings{}, Workspace{});
  std::vector<ControllerFrame> frames;
  for (int i = 0; i < 10; ++i) frames.push_back(at(i, {0.01 * i, 1.5, 0.0}, i < 8 ? 0.7 : 0.0));
  const auto events = run(g, frames);
  REQUIRE(events.size() == 1);
  const auto& stroke = std::get<StrokeEvent>(events[0].payload).stroke;
  CHECK(stroke.id == 1);
  CHECK(stroke.layer == Layer::automatic);
  REQUIRE(stroke.samples.size() == 8);
  for (int i = 0; i < 8; ++i) {
    CHECK((stroke.samples[i].position - Vec3(0.01 * i, 1.5, 0.0)).norm() < 1e-12);
    CHECK(stroke.samples[i].pressure == Approx(0.7));
    CHECK(stroke.samples[i].time == Approx(i * dt));
  }
  REQUIRE(stroke.view.has_value());
  // The view maps the head position to the eye origin.
  const Vec4 eye = stroke.view->view * Vec4(0, 1.6, 0.5, 1);
  CHECK(eye.head<3>().norm() < 1e-12);
  CHECK(events[0].time == Approx(8 * dt));
  CHECK(validate(stroke).empty());
}

TEST_CASE("a trigger press without movement records nothing", "[openxr]") {
  GestureInterpreter g(InputSettings{}, Workspace{});
  const auto events = run(g, {at(0, {0, 1, 0}, 1.0), at(1, {0, 1, 0}, 1.0), at(2, {0, 1, 0}, 0.0)});
  CHECK(events.empty());
}

TEST_CASE("two-hand zoom scales about the dominant hand and records the scale at release", "[openxr]") {
  GestureInterpreter g(InputSettings{}, Workspace{});
  std::vector<ControllerFrame> frames;
  for (int i = 0; i <= 10; ++i) {
    ControllerFrame f = at(i, {0.2 + 0.01 * i, 1.4, 0.0});
    f.hands[0].aim.position = {-0.2, 1.4, 0.0};
    f.hands[0].grab = f.hands[1].grab = i < 10;
    frames.push_back(f);
  }
  const Vec3 anchor_stage(0.2, 1.4, 0.0);  // dominant hand at the start: workspace point stays under it
  const auto events = run(g, frames);
  REQUIRE(events.size() == 1);
  const auto& ws = std::get<WorkspaceEvent>(events[0].payload).workspace;
  // d0 = 0.4, d = 0.49 at the last held frame (i = 9).
  CHECK(ws.scale == Approx(0.49 / 0.4).epsilon(1e-12));
  CHECK(g.workspace().scale == ws.scale);
  const Vec3 hand_last(0.29, 1.4, 0.0);
  CHECK((g.placement().to_stage(anchor_stage) - hand_last).norm() < 1e-12);
  // Thresholds scale as δ/s: a stroke drawn now carries the zoom.
  std::vector<ControllerFrame> draw;
  for (int i = 11; i < 15; ++i) draw.push_back(at(i, {0.01 * i, 1.0, 0.0}, 1.0));
  draw.push_back(at(15, {0, 1, 0}, 0.0));
  const auto more = run(g, draw);
  REQUIRE(more.size() == 1);
  const auto& stroke = std::get<StrokeEvent>(more[0].payload).stroke;
  CHECK(stroke.workspace_scale == ws.scale);
  CHECK((stroke.samples[0].position - g.placement().to_workspace(Vec3(0.11, 1.0, 0.0))).norm() < 1e-12);
}

TEST_CASE("one-hand grab moves the workspace rigidly with the hand", "[openxr]") {
  GestureInterpreter g(InputSettings{}, Workspace{});
  std::vector<ControllerFrame> frames;
  for (int i = 0; i < 5; ++i) {
    ControllerFrame f = at(i, {0.3, 1.2, 0.0});
    f.hands[0].aim.position = {-0.3 + 0.05 * i, 1.2, 0.0};
    f.hands[0].aim.orientation = Quat(Eigen::AngleAxisd(0.1 * i, Vec3::UnitY()));
    f.hands[0].grab = true;
    frames.push_back(f);
  }
  CHECK(run(g, frames).empty());  // moving is a view change, not an event
  // A workspace point held in the left hand follows it.
  const Vec3 w(-0.3, 1.2, 0.0);
  const auto& last = frames.back().hands[0].aim;
  CHECK((g.placement().to_stage(w) - last.position).norm() < 1e-12);
  const Vec3 v(-0.3, 1.3, 0.1);
  const Vec3 expected = last.orientation * (v - w) + last.position;
  CHECK((g.placement().to_stage(v) - expected).norm() < 1e-12);
  CHECK(g.placement().scale == 1.0);
}

TEST_CASE("buttons fire once per press, delete radius scales with zoom", "[openxr]") {
  Workspace ws;
  ws.scale = 2.0;
  GestureInterpreter g(InputSettings{}, ws);
  std::vector<ControllerFrame> frames;
  for (int i = 0; i < 6; ++i) {
    ControllerFrame f = at(i, {0.1, 1.0, 0.0});
    f.buttons[static_cast<int>(Command::undo)] = i == 1 || i == 2 || i == 4;
    f.buttons[static_cast<int>(Command::mode)] = i == 3;
    f.buttons[static_cast<int>(Command::delete_nearest)] = i == 5;
    frames.push_back(f);
  }
  const auto events = run(g, frames);
  REQUIRE(events.size() == 4);
  CHECK(std::holds_alternative<UndoEvent>(events[0].payload));
  CHECK(std::get<ModeEvent>(events[1].payload).mode == Layer::scaffold);
  CHECK(std::holds_alternative<UndoEvent>(events[2].payload));
  const auto& del = std::get<DeleteNearEvent>(events[3].payload);
  CHECK(del.radius == Approx(0.05 / 2.0));
  CHECK((del.point - Vec3(0.05, 0.5, 0.0)).norm() < 1e-12);
}

TEST_CASE("losing focus ends the stroke being drawn and later presses need a new press", "[openxr]") {
  GestureInterpreter g(InputSettings{}, Workspace{});
  auto f0 = at(0, {0, 1, 0}, 1.0), f1 = at(1, {0.1, 1, 0}, 1.0);
  f1.buttons[0] = true;
  auto lost = at(2, {0.2, 1, 0}, 1.0);
  lost.focused = false;
  auto back = at(3, {0.3, 1, 0}, 0.0);
  back.buttons[0] = true;  // still held: not a new press
  const auto events = run(g, {f0, f1, lost, back});
  REQUIRE(events.size() == 2);
  CHECK(std::holds_alternative<UndoEvent>(events[0].payload));
  CHECK(std::get<StrokeEvent>(events[1].payload).stroke.samples.size() == 2);
}

TEST_CASE("non-finite input is ignored, never recorded", "[openxr]") {
  GestureInterpreter g(InputSettings{}, Workspace{});
  auto bad = at(1, {std::nan(""), 1, 0}, 1.0);
  const auto events = run(g, {at(0, {0, 1, 0}, 1.0), bad, at(2, {0.1, 1, 0}, 1.0), at(3, {0.1, 1, 0}, 0.0)});
  REQUIRE(events.size() == 1);
  for (const auto& s : std::get<StrokeEvent>(events[0].payload).stroke.samples) CHECK(s.position.allFinite());
}

TEST_CASE("absurd poses and times from a glitching runtime never reach an event", "[openxr][reliability]") {
  // Found by fuzz/fuzz_openxr_input: a hand reported 1e300 m away made a
  // delete_near event the recording format refuses.
  GestureInterpreter g(InputSettings{}, Workspace{});
  std::vector<ControllerFrame> frames;
  for (int i = 0; i < 10; ++i) frames.push_back(at(i, {0.01 * i, 1.5, 0.0}, 0.7));
  frames[3].hands[1].aim.position.x() = -1e300;         // absurd position
  frames[5].hands[1].aim.orientation.coeffs().setZero();  // no rotation at all
  frames[6].time = 2e9;                                   // beyond the format's times
  frames.push_back(at(10, {0.1, 1.5, 0.0}, 0.0));
  ControllerFrame press = at(11, Vec3(1e300, 0, 0));
  press.buttons[static_cast<std::size_t>(Command::delete_nearest)] = true;
  frames.push_back(press);
  const auto events = run(g, frames);
  REQUIRE(events.size() == 1);
  const auto& stroke = std::get<StrokeEvent>(events[0].payload).stroke;
  CHECK(stroke.samples.size() == 7);  // frames 3 and 5 lost tracking, 6 is in the future
  for (const Event& e : events) CHECK_NOTHROW(to_json_line(e));
}
