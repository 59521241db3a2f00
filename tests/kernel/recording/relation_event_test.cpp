// The "relation" event (intended relations, e.g. synthetic ground truth):
// exact round trip, strict reading, and sessions that keep but ignore it.
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

Event relation(double t, ConstraintKind kind, std::vector<StrokeId> strokes,
               std::vector<double> parameters, std::string track = "ground_truth") {
  return Event{t, RelationEvent{std::move(track), kind, std::move(strokes), std::move(parameters)}};
}

}  // namespace

TEST_CASE("relation events are written in the documented form", "[recording][relation]") {
  const Event e = relation(2.5, ConstraintKind::intersection, {3, 7}, {0.25, 1.0});
  const std::string line = to_json_line(e);
  CHECK(line ==
        "{\"t\":2.5,\"type\":\"relation\",\"track\":\"ground_truth\",\"kind\":\"intersection\","
        "\"strokes\":[3,7],\"parameters\":[0.25,1.0]}");
  CHECK(event_type_name(e.payload) == "relation");
  CHECK(event_from_json_line(line) == e);
}

TEST_CASE("relation events of every kind survive write -> read -> write exactly", "[recording][relation]") {
  Recording rec;
  double t = 0.0;
  for (int k = 0; k < constraint_kind_count; ++k) {
    const auto kind = static_cast<ConstraintKind>(k);
    // Awkward doubles (not exactly representable in decimal) must come back bit for bit.
    rec.events.push_back(relation(t += 0.1, kind, {static_cast<StrokeId>(k + 1)}, {}));
    rec.events.push_back(relation(t += 0.1, kind, {1, 2, 18446744073709551615ull},
                                  {0.1 + 0.2, 1.0 / 3.0, 2.9999999999999996}, "other track"));
  }
  std::ostringstream out;
  write_recording(out, rec);
  std::istringstream in(out.str());
  const Recording back = parse_recording(in, "relations");
  REQUIRE(back == rec);
  std::ostringstream again;
  write_recording(again, back);
  CHECK(again.str() == out.str());
}

TEST_CASE("malformed relation events are rejected with the field named", "[recording][relation]") {
  const std::string head = R"({"t":1.0,"type":"relation",)";
  CHECK_THAT(event_line_error(head + R"("track":"gt","kind":"skewed","strokes":[1],"parameters":[]})"),
             Catch::Contains("unknown constraint kind 'skewed'") && Catch::Contains("parallel"));
  CHECK_THAT(event_line_error(head + R"("track":"gt","kind":"parallel","strokes":[],"parameters":[]})"),
             Catch::Contains("'strokes' must name at least one stroke"));
  CHECK_THAT(event_line_error(head + R"("track":"","kind":"parallel","strokes":[1],"parameters":[]})"),
             Catch::Contains("'track' must not be empty"));
  CHECK_THAT(event_line_error(head + R"("track":"gt","kind":"parallel","strokes":[-1],"parameters":[]})"),
             Catch::Contains("strokes[0]"));
  CHECK_THAT(event_line_error(head + R"("track":"gt","kind":"parallel","strokes":[1],"parameters":[null]})"),
             Catch::Contains("parameters[0]"));
  CHECK_THAT(event_line_error(head + R"("track":"gt","kind":"parallel","strokes":[1]})"),
             Catch::Contains("missing field 'parameters'"));
  CHECK_THAT(event_line_error(head + R"("track":"gt","kind":"parallel","strokes":[1],"parameters":[],"x":1})"),
             Catch::Contains("unknown field 'x'"));
  CHECK_THAT(event_line_error(R"({"t":1.0,"type":"scribble"})"), Catch::Contains("relation"));
}

namespace {
class NoCorrection : public Corrector {
 public:
  Correction correct(const Stroke&, const Sketch&) override { return {}; }
};
}  // namespace

TEST_CASE("sessions keep relation events by track and leave the sketch alone", "[session][relation]") {
  Session session({}, std::make_shared<NoCorrection>(), nullptr);
  const Event a = relation(1.0, ConstraintKind::parallel, {1, 2}, {});
  const Event b = relation(2.0, ConstraintKind::coincident_point, {2, 3}, {0.0, 1.0});
  const Event c = relation(3.0, ConstraintKind::planar, {4}, {}, "designer");
  for (const Event& e : {a, b, c}) {
    const StepReport r = session.handle(e);
    CHECK(r.event == EventKind::relation);
    CHECK(r.error.empty());
  }
  CHECK(session.sketch().network.curves().empty());
  CHECK(session.sketch().history.done.empty());
  REQUIRE(session.relations().size() == 2);
  REQUIRE(session.relations().at("ground_truth").size() == 2);
  CHECK(session.relations().at("ground_truth")[0] == std::get<RelationEvent>(a.payload));
  CHECK(session.relations().at("ground_truth")[1] == std::get<RelationEvent>(b.payload));
  CHECK(session.relations().at("designer").at(0) == std::get<RelationEvent>(c.payload));
}
