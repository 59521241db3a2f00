// Guideline strokes (Schmidt et al. 2009 §2.2): a stroke from a known point
// toward a vanishing point is a guideline; its end, like any stroke end, is
// a sample within δ of the intended one (§3.1, eq. 3).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "drawing.hpp"

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
