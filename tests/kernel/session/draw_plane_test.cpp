// 2D strokes drawn on a plane: lifting, validation, recording, and what each
// kind of corrector receives (world-space: lifted; pixels: as recorded).
#include <catch2/catch.hpp>

#include <sstream>

#include "sketchlab/draw_plane.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/recording/recording_writer.hpp"
#include "sketchlab/session.hpp"

using namespace sketchlab;

namespace {

Stroke pixel_stroke() {
  Stroke s;
  s.id = 1;
  s.view = View{};
  s.view->view = look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0});
  s.view->projection = perspective(0.7, 1.5, 0.1, 50.0);
  s.view->viewport = {10, 0, 600, 400};
  s.samples_are_pixels = true;
  s.draw_plane = plane_through({0, 0, -0.5}, {0, 0, 2});
  for (int i = 0; i < 12; ++i) {
    Sample x;
    x.position = Vec3(100 + 30 * i, 150 + 5 * i, 0);
    x.time = 0.1 * i;
    s.samples.push_back(x);
  }
  return s;
}

class Capture : public Corrector {
 public:
  explicit Capture(StrokeSpace space) : space_(space) {}
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    seen.push_back(stroke);
    return Correction{freehand_edit(stroke, sketch, {}), {}, {}, {}};
  }
  StrokeSpace stroke_space() const override { return space_; }
  std::vector<Stroke> seen;

 private:
  StrokeSpace space_;
};

}  // namespace

TEST_CASE("lift_to_draw_plane puts every sample on the plane under its pixel", "[draw_plane]") {
  const Stroke s = pixel_stroke();
  REQUIRE(validate(s).empty());
  std::string error;
  const Stroke lifted = lift_to_draw_plane(s, error);
  REQUIRE(error.empty());
  CHECK(!lifted.samples_are_pixels);
  CHECK(lifted.view == s.view);
  for (std::size_t i = 0; i < s.samples.size(); ++i) {
    CHECK(lifted.samples[i].position.z() == Approx(-0.5).margin(1e-9));
    const Vec3 px = world_to_pixel(*s.view, lifted.samples[i].position);
    CHECK((px.head<2>() - s.samples[i].position.head<2>()).norm() < 1e-6);
    CHECK(lifted.samples[i].time == s.samples[i].time);
  }
}

TEST_CASE("a plane behind the eye or edge-on is an error, not NaN", "[draw_plane]") {
  Stroke s = pixel_stroke();
  s.draw_plane = plane_through({0, 0, 5}, {0, 0, 1});  // behind the eye at z = 3
  std::string error;
  const Stroke same = lift_to_draw_plane(s, error);
  CHECK(error.find("misses the draw plane") != std::string::npos);
  CHECK(same == s);
  CHECK_THROWS_AS(plane_through({0, 0, 0}, {0, 0, 0}), std::invalid_argument);
}

TEST_CASE("validate and the recording format check the draw plane", "[draw_plane]") {
  Stroke s = pixel_stroke();
  s.draw_plane = Vec4(0, 0, 2, 0);
  CHECK(validate(s).find("draw plane") != std::string::npos);
  s = pixel_stroke();
  Recording rec{RecordingHeader{}, {Event{2.0, StrokeEvent{s}}}};
  std::stringstream text;
  write_recording(text, rec);
  CHECK(text.str().find("\"draw_plane\"") != std::string::npos);
  CHECK(parse_recording(text, "mem") == rec);
}

TEST_CASE("world-space correctors get the lifted stroke, pixel ones the recorded one",
          "[draw_plane][session]") {
  const Stroke s = pixel_stroke();
  auto world = std::make_shared<Capture>(StrokeSpace::world);
  auto pixels = std::make_shared<Capture>(StrokeSpace::pixels);
  Session a(Workspace{}, world, nullptr), b(Workspace{}, pixels, nullptr);
  CHECK(a.handle(Event{1.0, StrokeEvent{s}}).error.empty());
  CHECK(b.handle(Event{1.0, StrokeEvent{s}}).error.empty());
  REQUIRE(world->seen.size() == 1);
  REQUIRE(pixels->seen.size() == 1);
  CHECK(!world->seen[0].samples_are_pixels);
  CHECK(pixels->seen[0] == s);
  // The sketch keeps the stroke as recorded either way.
  CHECK(a.sketch().strokes.at(1) == s);
  // Correction off: the fallback fit is in world space too (on the plane).
  Session c(Workspace{}, world, nullptr);
  c.handle(Event{0.5, CorrectionEvent{false}});
  c.handle(Event{1.0, StrokeEvent{s}});
  REQUIRE(c.sketch().network.curves().size() == 1);
  for (const Vec3& p : c.sketch().network.curves().begin()->second.curve.control_points)
    CHECK(p.z() == Approx(-0.5).margin(1e-6));
}
