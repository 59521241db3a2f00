// Guideline strokes (Schmidt et al. 2009 §2.2): a stroke from a known point
// toward a vanishing point is a guideline; its end, like any stroke end, is
// a sample within δ of the intended one (§3.1, eq. 3).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "drawing.hpp"
#include "guideline.hpp"
#include "scaffold.hpp"

using namespace sketchlab;
using namespace sketchlab::analytic;
using namespace sketchlab::analytic::test;

TEST_CASE("a short guideline ending within δ of its vanishing line is one with guideline_reach (§3.1 eq. 3)",
          "[analytic][guideline]") {
  const View view = demo::tablet_view(Vec3(1.2, 1.4, 2.6), Vec3(0.0, 0.1, 0.0));
  const Vec3 x = Vec3::UnitX();
  const Vec3 B0(-0.3, 0, 0.2), B1 = B0 + 0.5 * x;
  // From B1 along x for ~60 px, the end 5 px aside: about 5° off the
  // vanishing direction (over the 3° angle test), well within δ ≥ 9.6 px.
  const Vec3 across = x.cross(B1 - eye_position(view)).normalized();
  const double px = std::tan(17.5 * std::numbers::pi / 180.0) / 500.0 * (B1 - eye_position(view)).norm();
  const Vec2 o = world_to_pixel(view, B1).head<2>();
  double s = 0.0;
  while ((world_to_pixel(view, B1 + s * x).head<2>() - o).norm() < 60.0) s += 0.1 * px;
  const Vec3 end = B1 + s * x + 5.0 * px * across;
  const Vec2 d_line = world_to_pixel(view, B1 + s * x).head<2>() - o;
  const Vec2 d_end = world_to_pixel(view, end).head<2>() - o;
  const double angle = std::acos(d_line.normalized().dot(d_end.normalized())) * 180.0 / std::numbers::pi;
  REQUIRE(angle > 3.5);
  REQUIRE(angle < 10.0);
  for (const double reach : {1.0, 0.0}) {
    AnalyticParams p;
    p.guideline_reach = reach;
    Drawing d(view, p);
    d.draw(demo::segment(B0, B1), 0.0);  // first stroke: the ground plane, x a vanishing direction
    const Stroke g = demo::projected_stroke(d.next++, view, {B1, end}, 0.0, 1, 960.0, 4.0, Layer::guide);
    const StepReport r = d.session.handle(Event{0.0, StrokeEvent{g}});
    if (reach > 0) {
      REQUIRE(stat(r, "guideline") == 1);
      const std::vector<NetworkCurve> added = d.added_by(g.id);
      REQUIRE(added.size() == 1);
      const Curve& l = added[0].curve;
      CHECK((l.control_points.front() - B1).norm() < 1e-9);
      const Vec3 dir = (l.control_points.back() - l.control_points.front()).normalized();
      CHECK(dir.cross(x).norm() < 1e-9);
    } else {
      CHECK(stat(r, "guideline") == 0);
      CHECK(d.added_by(g.id).empty());
    }
  }
}

TEST_CASE("guideline_fitness: of two directions nearly along the stroke, eq. 3 × eq. 4 picks the one segments share",
          "[analytic][guideline]") {
  const View view = demo::tablet_view(Vec3(1.2, 1.4, 2.6), Vec3(0.0, 0.1, 0.0));
  const Camera cam(view);
  const Vec3 x = Vec3::UnitX();
  const Vec3 O(0.3, 0.0, 0.0);  // the end of the first segment: a known point
  const Vec3 ray = (O - eye_position(view)).normalized();
  // A direction whose image line through O is about 1° off x's: x plus a
  // component along O's view ray (same image line) tilted out of that plane.
  const Vec3 d2 = (x + 0.5 * ray + 0.02 * x.cross(ray).normalized()).normalized();
  Sketch sketch;
  demo::add_curve(sketch, make_line(Vec3(0, 0, 0), O), Layer::scaffold);  // ground plane: x, z, up
  for (const double z : {0.15, 0.3, 0.45})  // three more segments along x
    demo::add_curve(sketch, make_line(Vec3(0, 0, z), Vec3(0.3, 0, z)), Layer::scaffold);
  demo::add_curve(sketch, make_line(Vec3(-0.3, 0, -0.3), Vec3(-0.3, 0, -0.3) + 0.2 * d2), Layer::scaffold);
  const Scaffold s = build_scaffold(sketch.network, Vec3::UnitY(), AnalyticParams{}.vanishing_merge);

  // The stroke: 150 px from O exactly along d2's image line.
  const Vec2 o = world_to_pixel(view, O).head<2>();
  double t = 0.0;
  while ((world_to_pixel(view, O + t * d2).head<2>() - o).norm() < 150.0) t += 1e-4;
  Stroke2d stroke;
  for (int i = 0; i <= 10; ++i) stroke.points.push_back(world_to_pixel(view, O + 0.1 * i * t * d2).head<2>());
  stroke.delta.assign(stroke.points.size(), 0.1 * view.dpi);  // δ_min
  stroke.length = (stroke.points.back() - o).norm();
  const Vec2 along_x = world_to_pixel(view, O + 1e-3 * x).head<2>() - o;
  const double angle =
      std::acos(along_x.normalized().dot((stroke.points.back() - o).normalized())) * 180.0 / std::numbers::pi;
  REQUIRE(angle > 0.3);  // x passes the 3° test too, with its end off its line
  REQUIRE(angle < 3.0);

  // The smallest angle: d2, which the stroke follows exactly.
  AnalyticParams by_angle;
  by_angle.guideline_fitness = false;
  const auto g_angle = detect_guideline(s, cam, stroke, by_angle, true);
  REQUIRE(g_angle);
  CHECK((g_angle->origin - O).norm() < 1e-9);
  CHECK(g_angle->direction.dot(d2) > 1.0 - 1e-12);

  // F = S·G (§3.1): S(x) = exp(−(off/δ)²) > 0.9 with off = 150 px·sin(angle),
  // G(x) = 1 + 4/5 against G(d2) = 1 + 1/5 (eq. 4's direction term).
  const auto g_fit = detect_guideline(s, cam, stroke, AnalyticParams{}, true);
  REQUIRE(g_fit);
  CHECK((g_fit->origin - O).norm() < 1e-9);
  CHECK(g_fit->direction.dot(x) > 1.0 - 1e-12);
  CHECK_FALSE(g_fit->image_parallel);
}
