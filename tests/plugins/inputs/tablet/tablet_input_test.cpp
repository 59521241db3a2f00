#include <catch2/catch.hpp>

#include "sketchlab/draw_plane.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/recording/recording_writer.hpp"
#include "tablet_input.hpp"

using namespace sketchlab;
using namespace sketchlab::tablet;

namespace {

PointerContext context_at(Layer layer) {
  PointerContext c;
  c.view.view = look_at({0, 0, 2}, {0, 0, 0}, {0, 1, 0});
  c.view.projection = perspective(0.6, 1.0, 0.01, 100.0);
  c.view.viewport = {0, 0, 400, 400};
  c.draw_plane = plane_through({0, 0, 0}, {0, 0, 1});
  c.layer = layer;
  return c;
}

void draw_line(TabletInput& in, Vec2 a, Vec2 b, double t0, int n, double pressure = 1.0) {
  in.pen_down({a, t0, pressure}, context_at(Layer::shape));
  for (int i = 1; i < n; ++i)
    in.pen_move({a + (b - a) * i / (n - 1.0), t0 + 0.01 * i, pressure});
  in.pen_up({b, t0 + 0.01 * n, pressure});
}

}  // namespace

TEST_CASE("down-move-up makes one 2D stroke with view, plane, times and pressure", "[tablet]") {
  TabletInput in({});
  draw_line(in, {100, 100}, {300, 120}, 1.0, 20, 0.4);
  auto e = in.next();
  REQUIRE(e);
  REQUIRE(!in.next());
  const auto& s = std::get<StrokeEvent>(e->payload).stroke;
  CHECK(s.id == 1);
  CHECK(s.is_2d());
  CHECK(s.layer == Layer::shape);
  REQUIRE(s.draw_plane);
  CHECK(validate(s).empty());
  CHECK(s.samples.size() == 20);  // the up sample repeats the last move: skipped
  CHECK(s.samples.front().position == Vec3(100, 100, 0));
  CHECK(s.samples.back().position.head<2>().isApprox(Vec2(300, 120)));
  for (std::size_t i = 1; i < s.samples.size(); ++i)
    CHECK(s.samples[i].time >= s.samples[i - 1].time);
  for (const auto& x : s.samples) CHECK(x.pressure == 0.4);
  CHECK(e->time == s.samples.back().time);
}

TEST_CASE("clicks and non-finite samples do not make strokes", "[tablet]") {
  TabletInput in({});
  in.pen_down({{10, 10}, 0.0, 1.0}, context_at(Layer::free));
  in.pen_up({{11, 10}, 0.1, 1.0});
  CHECK(!in.next());
  in.pen_down({{10, 10}, 0.2, 1.0}, context_at(Layer::free));
  in.pen_move({{std::nan(""), 10}, 0.3, 1.0});
  in.pen_move({{50, 10}, 0.4, std::nan("")});
  in.pen_up({{80, 10}, 0.5, 2.0});
  auto e = in.next();
  REQUIRE(e);
  const auto& s = std::get<StrokeEvent>(e->payload).stroke;
  CHECK(s.samples.size() == 3);
  CHECK(s.samples[1].pressure == 1.0);  // NaN pressure -> 1
  CHECK(s.samples[2].pressure == 1.0);  // clamped to [0, 1]
  CHECK(s.id == 1);                     // the click used no id
}

TEST_CASE("commands and strokes come out in order with non-decreasing times", "[tablet]") {
  TabletInput in({});
  in.set_next_stroke_id(7);
  draw_line(in, {0, 0}, {100, 0}, 2.0, 5);
  in.command(Event{1.0, UndoEvent{}});  // earlier clock time: clamped
  in.pen_down({{0, 0}, 3.0, 1.0}, context_at(Layer::scaffold));
  in.pen_move({{0, 50}, 3.1, 1.0});
  in.command(Event{3.2, RedoEvent{}});  // finishes the open stroke first
  in.close();
  std::vector<Event> events;
  while (auto e = in.next()) events.push_back(*e);
  CHECK(in.next().is_ended());
  REQUIRE(events.size() == 4);
  CHECK(std::get<StrokeEvent>(events[0].payload).stroke.id == 7);
  CHECK(std::holds_alternative<UndoEvent>(events[1].payload));
  CHECK(events[1].time == events[0].time);
  CHECK(std::get<StrokeEvent>(events[2].payload).stroke.id == 8);
  CHECK(std::holds_alternative<RedoEvent>(events[3].payload));
  for (std::size_t i = 1; i < events.size(); ++i) CHECK(events[i].time >= events[i - 1].time);
}

TEST_CASE("tablet strokes round-trip through a recording and lift onto their plane",
          "[tablet]") {
  TabletInput in({});
  draw_line(in, {50, 200}, {350, 260}, 0.5, 30, 0.7);
  Recording rec{in.header(), {*in.next()}};
  const auto file = std::filesystem::temp_directory_path() / "sketchlab_tablet_roundtrip.jsonl";
  write_recording(file, rec, true);
  const Recording back = read_recording(file);
  std::filesystem::remove(file);
  CHECK(back == rec);
  const Stroke& s = std::get<StrokeEvent>(back.events[0].payload).stroke;
  std::string error;
  const Stroke lifted = lift_to_draw_plane(s, error);
  REQUIRE(error.empty());
  CHECK(!lifted.samples_are_pixels);
  for (std::size_t i = 0; i < s.samples.size(); ++i) {
    CHECK(std::abs(lifted.samples[i].position.z()) < 1e-9);  // on the plane z = 0
    const Vec3 px = world_to_pixel(*s.view, lifted.samples[i].position);
    CHECK((px.head<2>() - s.samples[i].position.head<2>()).norm() < 1e-6);
  }
}

TEST_CASE("the tablet plugin loads and the host makes it as a PointerInput", "[tablet]") {
  PluginHost host;
  host.load_directories({SKETCHLAB_BUILD_PLUGIN_DIR});
  CHECK(host.pointer_input_names() == std::vector<std::string>{"tablet"});
  CHECK_THROWS_WITH(host.make_pointer_input("replay", {}),
                    "input 'replay' is not a pointer input; pointer inputs: tablet");
  const std::shared_ptr<PointerInput> pointer = host.make_pointer_input("tablet", {{"dpi", 120.0}});
  REQUIRE(pointer);
  const std::shared_ptr<Input> input = pointer;
  pointer->pen_down({{0, 0}, 0.0, 1.0}, context_at(Layer::free));
  pointer->pen_up({{40, 0}, 0.1, 1.0});
  auto e = input->next();
  REQUIRE(e);
  CHECK(std::get<StrokeEvent>(e->payload).stroke.view->dpi == 120.0);
  CHECK(input->header().units == "px");
}

TEST_CASE("next() tells 'nothing yet' from 'ended'", "[tablet][input]") {
  TabletInput in({});
  CHECK(in.next().state() == NextEvent::State::not_ready);  // open, nothing drawn
  draw_line(in, {100, 100}, {300, 120}, 1.0, 5);
  CHECK(in.next().state() == NextEvent::State::event);
  CHECK(in.next().state() == NextEvent::State::not_ready);
  draw_line(in, {100, 200}, {300, 220}, 2.0, 5);
  in.close();
  CHECK(in.next().has_event());  // what was drawn before closing still comes out
  CHECK(in.next().is_ended());
  CHECK(in.next().is_ended());
}
