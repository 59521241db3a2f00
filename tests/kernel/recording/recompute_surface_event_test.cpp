// The "recompute_surface" event (global surfacers such as Hermite RBF build
// their surface on request): exact round trip, strict reading, and sessions
// that forward it to Surfacer::recompute.
#include <catch2/catch.hpp>
#include <sstream>
#include <stdexcept>

#include "event_line_error.hpp"
#include "sketchlab/recording/event_json.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/recording/recording_writer.hpp"
#include "sketchlab/session.hpp"

using namespace sketchlab;
using sketchlab::test::event_line_error;

namespace {

// Adds each stroke as a straight curve between its end samples.
class LineCorrector : public Corrector {
 public:
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    Correction c;
    NetworkCurve nc;
    nc.id = sketch.network.next_curve_id();
    nc.curve = make_line(stroke.samples.front().position, stroke.samples.back().position);
    nc.source_stroke = stroke.id;
    c.edit.curves_added.push_back(nc);
    return c;
  }
};

Event line_stroke(double t) {
  Stroke s;
  s.id = 1;
  s.samples.resize(2);
  s.samples[1].position = Vec3::UnitX();
  return Event{t, StrokeEvent{s}};
}

// Adds one patch per recompute (replacing the previous one), nothing otherwise.
class CountingSurfacer : public Surfacer {
 public:
  SurfaceUpdate update(const Sketch&, const Edit&) override { return {}; }
  SurfaceUpdate command(const Sketch&, const SurfaceCommand&) override { return {}; }
  SurfaceUpdate recompute(const Sketch& sketch) override {
    ++calls;
    SurfaceUpdate u;
    for (const auto& [id, patch] : sketch.network.patches()) u.edit.patches_removed.push_back(id);
    Patch p;
    p.id = sketch.network.next_patch_id();
    p.automatic = true;
    p.mesh.vertices = {Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY()};
    p.mesh.faces = {{0, 1, 2}};
    p.boundary.push_back({sketch.network.curves().begin()->first, 0.0, 0.0, 0, 0});
    u.edit.patches_added.push_back(std::move(p));
    return u;
  }
  int calls = 0;
};

}  // namespace

TEST_CASE("recompute_surface events are written in the documented form", "[recording][recompute]") {
  const Event e{4.25, RecomputeSurfaceEvent{}};
  const std::string line = to_json_line(e);
  CHECK(line == "{\"t\":4.25,\"type\":\"recompute_surface\"}");
  CHECK(event_type_name(e.payload) == "recompute_surface");
  CHECK(event_from_json_line(line) == e);
}

TEST_CASE("recompute_surface events survive write -> read -> write exactly", "[recording][recompute]") {
  Recording rec;
  rec.events.push_back(Event{0.1 + 0.2, RecomputeSurfaceEvent{}});
  rec.events.push_back(Event{1.0, UndoEvent{}});
  rec.events.push_back(Event{1.0 / 3.0 + 1.0, RecomputeSurfaceEvent{}});
  std::ostringstream out;
  write_recording(out, rec);
  std::istringstream in(out.str());
  const Recording back = parse_recording(in, "recompute");
  REQUIRE(back == rec);
  std::ostringstream again;
  write_recording(again, back);
  CHECK(again.str() == out.str());
}

TEST_CASE("recompute_surface events with extra fields are rejected", "[recording][recompute]") {
  CHECK_THAT(event_line_error(R"({"t":1.0,"type":"recompute_surface","point":[0,0,0]})"),
             Catch::Contains("point"));
  CHECK_THAT(event_line_error(R"({"type":"recompute_surface"})"), Catch::Contains("'t'"));
}

TEST_CASE("sessions forward recompute_surface to the surfacer as an undoable step", "[session][recompute]") {
  auto surfacer = std::make_shared<CountingSurfacer>();
  Session s(Workspace{}, std::make_shared<LineCorrector>(), surfacer);
  REQUIRE(s.handle(line_stroke(0.5)).error.empty());
  StepReport r = s.handle(Event{1.0, RecomputeSurfaceEvent{}});
  CHECK(r.error.empty());
  CHECK(r.event == EventKind::recompute_surface);
  CHECK(r.patches_added == 1);
  r = s.handle(Event{2.0, RecomputeSurfaceEvent{}});
  CHECK(r.patches_added == 1);
  CHECK(r.patches_removed == 1);
  CHECK(surfacer->calls == 2);
  CHECK(s.sketch().network.patches().size() == 1);
  r = s.handle(Event{3.0, UndoEvent{}});
  CHECK(r.error.empty());
  CHECK(s.sketch().network.patches().size() == 1);
  CHECK(s.sketch().network.patches().begin()->first == 1);

  Session bare(Workspace{}, std::make_shared<LineCorrector>(), nullptr);
  CHECK_THAT(bare.handle(Event{1.0, RecomputeSurfaceEvent{}}).error, Catch::Contains("no surfacer"));
}
