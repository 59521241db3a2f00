#include "sketchlab/session.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "session_fixtures.hpp"

namespace {

using namespace sketchlab;
using test::FitCorrector;
using test::sampled_stroke;

class FailingCorrector : public Corrector {
 public:
  Correction correct(const Stroke&, const Sketch&) override {
    Correction c;
    c.error = "deliberate failure";
    return c;
  }
};

// A wobbly 3D stroke of ~30 cm starting at `origin`.
Stroke make_stroke(StrokeId id, const Vec3& origin, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, 0.001);
  return sampled_stroke(id, 40, id, 0.01, [&](int i) -> Vec3 {
    const double u = i / 39.0;
    return origin + Vec3(0.3 * u, 0.05 * std::sin(3 * u), 0.02 * u) + Vec3(noise(rng), noise(rng), noise(rng));
  });
}

Event at(double t, EventPayload p) { return Event{t, std::move(p)}; }

}  // namespace

TEST_CASE("undo equals folding one edit fewer, ids included", "[session]") {
  std::mt19937_64 rng(7);
  std::vector<Stroke> strokes;
  for (StrokeId i = 1; i <= 6; ++i) strokes.push_back(make_stroke(i, Vec3(0, 0.1 * i, 0), rng));

  auto fit = std::make_shared<FitCorrector>();
  Session with_undo({}, fit, nullptr);
  Session without({}, fit, nullptr);
  for (int i = 0; i < 5; ++i) {
    with_undo.handle(at(i, StrokeEvent{strokes[i]}));
    if (i != 4) without.handle(at(i, StrokeEvent{strokes[i]}));
  }
  REQUIRE(with_undo.handle(at(5, UndoEvent{})).error.empty());
  CHECK(with_undo.sketch().network == without.sketch().network);

  // A new stroke after the undo gets exactly the ids a fresh fold gives.
  with_undo.handle(at(6, StrokeEvent{strokes[5]}));
  without.handle(at(6, StrokeEvent{strokes[5]}));
  CHECK(with_undo.sketch().network == without.sketch().network);
  CHECK(with_undo.handle(at(7, RedoEvent{})).error == "nothing to redo");
}

TEST_CASE("redo restores the undone stroke exactly", "[session]") {
  std::mt19937_64 rng(8);
  auto fit = std::make_shared<FitCorrector>();
  Session s({}, fit, nullptr);
  s.handle(at(0, StrokeEvent{make_stroke(1, Vec3::Zero(), rng)}));
  s.handle(at(1, StrokeEvent{make_stroke(2, Vec3(0, 0.2, 0), rng)}));
  const Network before = s.sketch().network;
  s.handle(at(2, UndoEvent{}));
  s.handle(at(3, UndoEvent{}));
  CHECK(s.sketch().network.curves().empty());
  CHECK(s.handle(at(4, UndoEvent{})).error == "nothing to undo");
  s.handle(at(5, RedoEvent{}));
  s.handle(at(6, RedoEvent{}));
  CHECK(s.sketch().network == before);
  CHECK(live_strokes(s.sketch()) == std::vector<StrokeId>{1, 2});
}

TEST_CASE("bad strokes are refused with a reason and lose nothing", "[session]") {
  std::mt19937_64 rng(9);
  auto fit = std::make_shared<FitCorrector>();
  Session s({}, fit, nullptr);
  s.handle(at(0, StrokeEvent{make_stroke(1, Vec3::Zero(), rng)}));
  const Network before = s.sketch().network;

  Stroke nan_stroke = make_stroke(2, Vec3::Zero(), rng);
  nan_stroke.samples[3].position.x() = std::nan("");
  auto r = s.handle(at(1, StrokeEvent{nan_stroke}));
  CHECK_THAT(r.error, Catch::Contains("stroke 2"));

  Stroke empty;
  empty.id = 3;
  r = s.handle(at(2, StrokeEvent{empty}));
  CHECK_FALSE(r.error.empty());

  r = s.handle(at(3, StrokeEvent{make_stroke(1, Vec3(1, 0, 0), rng)}));
  CHECK_THAT(r.error, Catch::Contains("already used"));

  CHECK(s.sketch().network == before);
  CHECK(fit->calls == 1);
}

TEST_CASE("a failing corrector keeps the raw stroke and changes nothing", "[session]") {
  std::mt19937_64 rng(10);
  Session s({}, std::make_shared<FailingCorrector>(), nullptr);
  const auto r = s.handle(at(0, StrokeEvent{make_stroke(1, Vec3::Zero(), rng)}));
  CHECK(r.error == "corrector: deliberate failure");
  CHECK(s.sketch().network.curves().empty());
  CHECK(s.sketch().strokes.count(1) == 1);
  CHECK(s.sketch().history.done.empty());
}

TEST_CASE("correction off uses the freehand fit, deletions are undoable", "[session]") {
  std::mt19937_64 rng(11);
  auto fit = std::make_shared<FitCorrector>();
  Session s({}, fit, nullptr);
  s.handle(at(0, CorrectionEvent{false}));
  s.handle(at(1, StrokeEvent{make_stroke(1, Vec3::Zero(), rng)}));
  CHECK(fit->calls == 0);
  REQUIRE(s.sketch().network.curves().size() == 1);
  s.handle(at(2, CorrectionEvent{true}));
  s.handle(at(3, StrokeEvent{make_stroke(2, Vec3(0, 0.5, 0), rng)}));
  CHECK(fit->calls == 1);

  const Network two = s.sketch().network;
  auto r = s.handle(at(4, DeleteStrokeEvent{2}));
  CHECK(r.curves_removed == 1);
  CHECK(curves_of_stroke(s.sketch(), 2).empty());
  s.handle(at(5, UndoEvent{}));
  CHECK(s.sketch().network == two);

  // Delete the curve nearest to a point on stroke 1, within 2 cm.
  r = s.handle(at(6, DeleteNearEvent{Vec3(0.15, 0.05, 0.01), 0.02}));
  CHECK(r.curves_removed == 1);
  CHECK(curves_of_stroke(s.sketch(), 1).empty());
  r = s.handle(at(7, DeleteNearEvent{Vec3(5, 5, 5), 0.05}));
  CHECK_THAT(r.error, Catch::Contains("no curve"));
}

TEST_CASE("workspace and mode events change the state plugins read", "[session]") {
  std::mt19937_64 rng(12);
  Session s({}, std::make_shared<FitCorrector>(), nullptr);
  Workspace ws;
  ws.scale = 2.0;
  ws.mirror_enabled = true;
  s.handle(at(0, WorkspaceEvent{ws}));
  s.handle(at(1, ModeEvent{Layer::scaffold}));
  CHECK(s.sketch().workspace == ws);
  s.handle(at(2, StrokeEvent{make_stroke(1, Vec3::Zero(), rng)}));
  CHECK(s.sketch().strokes.at(1).layer == Layer::scaffold);
  CHECK(s.sketch().network.curves().begin()->second.layer == Layer::scaffold);
  ws.scale = 0.0;
  CHECK_THAT(s.handle(at(3, WorkspaceEvent{ws})).error, Catch::Contains("scale"));
  CHECK(s.sketch().workspace.scale == 2.0);
}
