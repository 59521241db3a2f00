// The case metrics on small hand-made sessions whose figures are known
// exactly: counts, events refused, latency percentiles, the dangling endpoint
// ratio (CASSIE CHI 2021 §6.4.2) and agreement with a reference track.
#include <catch2/catch.hpp>

#include "session_fixtures.hpp"
#include "sketchlab/lab/metrics.hpp"

using namespace sketchlab;

namespace {

Stroke line_stroke(StrokeId id, const Vec3& a, const Vec3& b) {
  return test::sampled_stroke(id, 20, double(id), 0.01, [&](int i) -> Vec3 { return a + (b - a) * (i / 19.0); });
}

// Two separate straight strokes through the freehand fit: two curves, four
// dangling ends, no node.
ReplayResult two_lines() {
  ReplayResult r{"fit", RecordingHeader{}, Session(Workspace{}, std::make_shared<test::FitCorrector>(), nullptr), {}};
  r.steps.push_back(r.session.handle(Event{1.0, StrokeEvent{line_stroke(1, {0, 0, 0}, {0.3, 0, 0})}}));
  r.steps.push_back(r.session.handle(Event{2.0, StrokeEvent{line_stroke(2, {0, 0.2, 0}, {0.3, 0.2, 0})}}));
  return r;
}

}  // namespace

TEST_CASE("metrics: counts, refused events and the dangling endpoint ratio", "[lab][metrics]") {
  ReplayResult r = two_lines();
  // A step whose plugin failed: counted as refused, not as a latency.
  StepReport refused;
  refused.event = EventKind::stroke;
  refused.corrected = true;
  refused.latency_ms = 1e3;
  refused.error = "corrector: failed";
  r.steps.push_back(refused);
  const CaseMetrics m = compute_metrics(r);
  CHECK(m.values.at("curves") == 2);
  CHECK(m.values.at("strokes") == 2);
  CHECK(m.values.at("nodes") == 0);
  CHECK(m.values.at("patches") == 0);
  CHECK(m.values.at("events_refused") == 1);
  CHECK(m.values.at("dangling_endpoint_ratio") == 1.0);
  CHECK(m.values.at("input_deviation_max_m") < 1e-9);
  CHECK(m.values.count("ref_cassie_compared") == 0);  // no reference track
  CHECK(m.values.count("gt_distance_mean_m") == 0);   // no ground truth
}

TEST_CASE("metrics: latency percentiles over the corrected strokes only", "[lab][metrics]") {
  ReplayResult r = two_lines();
  r.steps.push_back(r.session.handle(Event{3.0, StrokeEvent{line_stroke(3, {0, 0.4, 0}, {0.3, 0.4, 0})}}));
  r.steps.push_back(r.session.handle(Event{4.0, UndoEvent{}}));
  REQUIRE(r.steps.size() == 4);
  r.steps[0].latency_ms = 3.0;
  r.steps[1].latency_ms = 1.0;
  r.steps[2].latency_ms = 2.0;
  r.steps[3].latency_ms = 100.0;  // the undo: not a stroke
  const CaseMetrics m = compute_metrics(r);
  CHECK(m.values.at("latency_p50_ms") == 2.0);
  CHECK(m.values.at("latency_max_ms") == 3.0);
  CHECK(m.values.at("curves") == 2);  // the third stroke was undone
}

TEST_CASE("metrics: a reference track equal to the output agrees fully, a shifted one by its shift",
          "[lab][metrics]") {
  for (const double shift : {0.0, 0.01}) {
    ReplayResult r = two_lines();
    for (const auto& [id, c] : r.session.sketch().network.curves()) {
      Curve ref = c.curve;
      for (Vec3& p : ref.control_points) p.z() += shift;
      r.steps.push_back(r.session.handle(Event{5.0, ReferenceEvent{c.source_stroke, "cassie", ref}}));
    }
    const CaseMetrics m = compute_metrics(r);
    CHECK(m.values.at("ref_cassie_compared") == 2);
    CHECK(m.values.at("ref_cassie_endpoint_mean_m") == Approx(shift).margin(1e-12));
    CHECK(m.values.at("ref_cassie_control_mean_m") == Approx(shift).margin(1e-12));
    // Every end dangles on both sides (1 mm snap tolerance, 0.2 m apart).
    CHECK(m.values.at("ref_cassie_snap_agreement") == 1.0);
  }
}
