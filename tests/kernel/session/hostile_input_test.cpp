// What a Session does with plugins that overrun, throw or return garbage and
// with strokes it cannot use (issue 17): each becomes that event's error, and
// the session goes on.
#include <catch2/catch.hpp>
#include <chrono>
#include <functional>
#include <limits>
#include <stdexcept>

#include "session_fixtures.hpp"
#include "sketchlab/plugin/budget.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/session.hpp"
#include "test_paths.hpp"

namespace {

using namespace sketchlab;
using test::FitCorrector;
using test::sampled_stroke;

// Fits like FitCorrector, but spins (checking the budget, as correctors do at
// their loop heads) on strokes with an odd id.
class SpinningCorrector : public FitCorrector {
 public:
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    if (stroke.id % 2 == 1)
      for (;;) check_budget();
    return FitCorrector::correct(stroke, sketch);
  }
};

// Throws out of correct(): what a plugin built without the wrappers of
// plugin_api.hpp would let escape.
class ThrowingCorrector : public Corrector {
 public:
  Correction correct(const Stroke&, const Sketch&) override { throw std::runtime_error("plugin bug"); }
};

class SpinningSurfacer : public Surfacer {
 public:
  SurfaceUpdate update(const Sketch&, const Edit&) override {
    for (;;) check_budget();
  }
  SurfaceUpdate command(const Sketch&, const SurfaceCommand&) override { throw std::logic_error("unused"); }
};

Stroke line_stroke(StrokeId id, double y) {
  return sampled_stroke(id, 20, double(id), 0.01, [&](int i) -> Vec3 { return {0.015 * i, y, 0.0}; });
}

Event stroke_at(double t, Stroke s) { return Event{t, StrokeEvent{std::move(s)}}; }

double seconds_of(const std::function<void()>& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

TEST_CASE("a corrector that overruns its time budget fails that stroke only", "[session][budget]") {
  Session session({}, std::make_shared<SpinningCorrector>(), nullptr, {}, 0.05);
  REQUIRE(session.handle(stroke_at(0, line_stroke(2, 0.0))).error.empty());
  StepReport spun;
  const double took = seconds_of([&] { spun = session.handle(stroke_at(1, line_stroke(3, 0.1))); });
  CHECK(spun.error == "stroke 3: time budget of 0.05 s exceeded");
  CHECK(spun.stroke == StrokeId{3});
  CHECK(took < 1.0);
  // The raw stroke stays recorded, the sketch is otherwise untouched and the
  // next stroke is corrected with a fresh budget.
  CHECK(session.sketch().strokes.count(3) == 1);
  CHECK(session.sketch().network.curves().size() == 1);
  CHECK(session.handle(stroke_at(2, line_stroke(4, 0.2))).error.empty());
  CHECK(session.sketch().network.curves().size() == 2);
}

TEST_CASE("a surfacer that overruns keeps the stroke's curve and reports the surfacer", "[session][budget]") {
  Session session({}, std::make_shared<FitCorrector>(), std::make_shared<SpinningSurfacer>(), {}, 0.05);
  const StepReport r = session.handle(stroke_at(0, line_stroke(2, 0.0)));
  CHECK(r.error == "surfacer: time budget of 0.05 s exceeded");
  CHECK(session.sketch().network.curves().size() == 1);
}

TEST_CASE("BudgetScope: nested scopes restore the outer budget, none means no limit", "[session][budget]") {
  CHECK(budget_left() == std::numeric_limits<double>::infinity());
  CHECK_NOTHROW(check_budget());
  {
    const BudgetScope outer(100.0);
    CHECK(budget_left() > 99.0);
    {
      const BudgetScope inner(1e-9);
      CHECK_THROWS_AS(check_budget(), BudgetExceeded);
    }
    CHECK(budget_left() > 99.0);
    CHECK_NOTHROW(check_budget());
  }
  CHECK(budget_left() == std::numeric_limits<double>::infinity());
  CHECK_THROWS_AS(BudgetScope(0.0), std::invalid_argument);
  CHECK_THROWS_AS(Session({}, std::make_shared<FitCorrector>(), nullptr, {}, -1.0), std::invalid_argument);
}

TEST_CASE("an exception escaping a plugin becomes the stroke's error", "[session]") {
  Session session({}, std::make_shared<ThrowingCorrector>(), nullptr);
  StepReport r;
  REQUIRE_NOTHROW(r = session.handle(stroke_at(0, line_stroke(1, 0.0))));
  CHECK(r.error == "plugin bug");
  CHECK(session.sketch().strokes.count(1) == 1);
}

TEST_CASE("a singular camera is refused per stroke, the session goes on", "[session][reliability]") {
  // Issue 17, D5 (reproducer C0): pixel_to_ray threw out of Session::handle,
  // failing the whole case with nothing written.
  const Recording rec = read_recording(test::source_path("tests/fixtures/reliability/C0_singular_camera.jsonl"));
  Session session(rec.header.workspace, std::make_shared<FitCorrector>(), nullptr);
  int refused = 0;
  for (const Event& e : rec.events) {
    StepReport r;
    REQUIRE_NOTHROW(r = session.handle(e));
    CHECK_THAT(r.error, Catch::EndsWith(": its camera (projection * view) is not invertible"));
    refused += !r.error.empty();
  }
  CHECK(refused == 4);
  // A good stroke afterwards is corrected.
  CHECK(session.handle(stroke_at(100, line_stroke(50, 0.0))).error.empty());
}

TEST_CASE("strokes beyond the recording format's bounds or sample limit are refused", "[session][reliability]") {
  Session session({}, std::make_shared<FitCorrector>(), nullptr);
  Stroke far = line_stroke(1, 0.0);
  far.samples[5].position.x() = 1e12;
  CHECK(session.handle(stroke_at(0, far)).error ==
        "stroke 1 sample 5 has a coordinate of magnitude 1e+12; strokes are limited to 1e+06 m, as "
        "recordings are");
  Stroke late = line_stroke(2, 0.0);
  late.samples.back().time = 2e9;
  CHECK(session.handle(stroke_at(0, late)).error ==
        "stroke 2 sample 19 has time 2e+09; strokes are limited to 1e+09 s, as recordings are");
  const Stroke huge = sampled_stroke(3, int(max_stroke_samples) + 1, 0.0, 1e-4,
                                     [](int i) -> Vec3 { return {1e-6 * i, 0.0, 0.0}; });
  CHECK(session.handle(stroke_at(0, huge)).error ==
        "stroke 3 has 100001 samples; a stroke may have at most 100000");
  CHECK(session.sketch().strokes.empty());
  CHECK(session.handle(stroke_at(1, line_stroke(4, 0.0))).error.empty());
}
