// JustDrawIt-style sessions: multi-stroke curves and a second view.
#include <catch2/catch.hpp>
#include <set>

#include "models.hpp"
#include "multi_view.hpp"
#include "relations.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "synthetic_test_support.hpp"

using namespace sketchlab;
using namespace sketchlab::synthetic;

TEST_CASE("a JustDrawIt session draws each curve in two strokes, then oversketches it from a second view",
          "[synthetic][multi_view]") {
  SynthesisParams p = support::perfect("chair", Modality::tablet);
  p.style = DrawingStyle::justdrawit;
  const Recording rec = synthesize_session(p);
  const auto drawn = support::drawn(rec);
  const GroundTruthNetwork plan = plan_drawing(make_chair(model_center, 0.3));
  REQUIRE(drawn.size() == 3 * plan.curves.size());  // chair curves are all open
  std::set<StrokeId> first_strokes;
  const Vec3 eye1 = eye_position(*drawn.front().stroke.view), eye2 = eye_position(*drawn.back().stroke.view);
  CHECK((eye1 - eye2).norm() > 0.1);
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    INFO("stroke " << drawn[i].stroke.id);
    // Every stroke carries its whole intended curve as ground truth.
    const std::size_t curve = i < 2 * plan.curves.size() ? i / 2 : i - 2 * plan.curves.size();
    CHECK(drawn[i].truth.control_points == plan.curves[curve].curve.control_points);
    const bool second_view = i >= 2 * plan.curves.size();
    CHECK((eye_position(*drawn[i].stroke.view) - (second_view ? eye2 : eye1)).norm() < 1e-12);
    if (i < 2 * plan.curves.size() && i % 2 == 0) first_strokes.insert(drawn[i].stroke.id);
  }
  for (const RelationEvent& r : support::relations(rec))
    for (StrokeId s : r.strokes) CHECK(first_strokes.count(s));
  CHECK(rec.header.source.at("style") == "justdrawit");
  p.modality = Modality::vr;
  CHECK_THROWS_WITH(synthesize_session(p), Catch::Contains("modality=tablet"));
}
