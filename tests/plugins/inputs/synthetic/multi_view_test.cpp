// JustDrawIt-style sessions: multi-stroke curves and a second view.
#include <catch2/catch.hpp>
#include <set>

#include "models.hpp"
#include "multi_view.hpp"
#include "relations.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/draw_plane.hpp"
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

TEST_CASE("a JustDrawIt session draws each curve on the draw plane placed for it", "[synthetic][multi_view]") {
  for (const std::string model : {"cube", "mug", "chair", "lamp"}) {
    INFO(model);
    SynthesisParams p = support::perfect(model, Modality::tablet);
    p.style = DrawingStyle::justdrawit;
    const Recording rec = synthesize_session(p);
    const Vec3 eye = eye_position(*support::drawn(rec).front().stroke.view);
    for (const auto& d : support::drawn(rec)) {
      INFO("stroke " << d.stroke.id);
      REQUIRE(d.stroke.draw_plane);
      const Vec4& plane = *d.stroke.draw_plane;
      const Vec3 n = plane.head<3>();
      // The plane holds the whole intended curve (a planar curve's own plane).
      for (const Vec3& q : d.truth.control_points) CHECK(std::abs(n.dot(q) - plane[3]) < 1e-12);
      if (d.truth.kind == CurveKind::line) {
        // A line's plane is the one through it that faces the first eye best
        // (kept for the oversketch from the second view).
        const Vec3 a = d.truth.control_points.front(), dir = (d.truth.control_points.back() - a).normalized();
        Vec3 facing = eye - a;
        facing -= facing.dot(dir) * dir;
        CHECK(n.dot(facing.normalized()) > 1 - 1e-12);
      }
      // Noise-free pixels lifted onto the plane lie on the intended curve.
      std::string error;
      const Stroke lifted = lift_to_draw_plane(d.stroke, error);
      REQUIRE(error.empty());
      for (const Sample& s : lifted.samples) CHECK(closest_point(d.truth, s.position).distance < 1e-9);
    }
  }
  SynthesisParams p = support::perfect("cube", Modality::tablet);
  p.style = DrawingStyle::justdrawit;
  p.draw_planes = false;
  const Recording rec = synthesize_session(p);
  const auto drawn = support::drawn(rec);
  CHECK(*drawn.front().stroke.draw_plane == *drawn[1].stroke.draw_plane);  // the view plane through the model
  CHECK(rec.header.source.at("draw_planes") == "false");
}

TEST_CASE("a JustDrawIt draw plane is refused for a curve that is not planar", "[synthetic][multi_view]") {
  Curve twisted;
  twisted.control_points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(1, 1, 1)};
  CHECK_THROWS_WITH(placed_draw_plane(twisted, Vec3(5, 5, 5)), Catch::Contains("planar"));
  CHECK_THROWS_WITH(placed_draw_plane(make_line(Vec3(0, 0, 0), Vec3(1, 0, 0)), Vec3(3, 0, 0)), Catch::Contains("end-on"));
}

TEST_CASE("a JustDrawIt session draws a closed curve from a free stretch, on over its start", "[synthetic][multi_view]") {
  const Curve rim = make_circle(Vec3(0, 1, 0), Vec3::UnitX(), -Vec3::UnitZ(), 0.1);
  const Curve from = loop_from(rim, loop_start);
  CHECK(from.closed);
  CHECK(validate(from).empty());
  CHECK((from.control_points.front() - evaluate(rim, loop_start)).norm() < 1e-12);
  const Curve drawn = closing_loop(rim);
  CHECK_FALSE(drawn.closed);
  CHECK(validate(drawn).empty());
  // Once round the same points, then on over the start by closing_overlap.
  for (int i = 0; i <= 100; ++i) CHECK(closest_point(rim, evaluate(drawn, drawn.t_max() * i / 100.0)).distance < 1e-9);
  CHECK((evaluate(drawn, from.t_max()) - from.control_points.front()).norm() < 1e-12);
  CHECK((drawn.control_points.back() - evaluate(from, closing_overlap * from.t_max())).norm() < 1e-12);
  CHECK_THROWS_WITH(closing_loop(make_line(Vec3(0, 0, 0), Vec3(1, 0, 0))), Catch::Contains("closed"));

  // In the session: the mug's closed curves are drawn so in the first view.
  SynthesisParams p = support::perfect("mug", Modality::tablet);
  p.style = DrawingStyle::justdrawit;
  const auto strokes = support::drawn(synthesize_session(p));
  const Vec3 eye1 = eye_position(*strokes.front().stroke.view);
  int loops = 0;
  for (const auto& d : strokes) {
    if (!d.truth.closed || (eye_position(*d.stroke.view) - eye1).norm() > 1e-12) continue;
    ++loops;
    const Vec3 first = world_to_pixel(*d.stroke.view, evaluate(d.truth, loop_start));
    CHECK((d.stroke.samples.front().position.head<2>() - first.head<2>()).norm() < 1e-6);
  }
  CHECK(loops == 2);
}
