// §3.1 Figure 7c: a line stroke ending where it crosses the projection of an
// inferred curve ends ON that 3D curve; an end far from the curve's
// projection gets no such constraint.
#include <catch2/catch.hpp>
#include <cmath>

#include "analytic_corrector.hpp"
#include "sketchlab/camera.hpp"
#include "curve_crossing.hpp"
#include "demo_scenes.hpp"
#include "line_inference.hpp"
#include "scaffold.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "stroke_2d.hpp"

using namespace sketchlab;
using namespace sketchlab::analytic;

namespace {

// A quarter circle (cubic Bézier, k = 0.5523) of radius r about c in the
// horizontal plane through c.
Curve quarter_arc(const Vec3& c, double r) {
  const double k = 0.5522847498;
  const Vec3 e1 = Vec3::UnitX(), e2 = -Vec3::UnitZ();
  Curve arc;
  arc.kind = CurveKind::bezier;
  arc.control_points = {c + r * e1, c + r * e1 + k * r * e2, c + r * e2 + k * r * e1, c + r * e2};
  arc.sharp = {false, false};
  return arc;
}

struct Scene {
  View view = demo::tablet_view(Vec3(0.2, 1.6, 3.2), Vec3(0.1, 0.2, -0.3));
  Sketch sketch;
  Curve arc = quarter_arc(Vec3(0.4, 0.2, -0.4), 0.35);
  CurveId arc_id = 0;
  Vec3 T0{-0.3, 0.5, -0.4};
  Scene() {
    const Vec3 B0(-0.3, 0, -0.4), B1 = B0 + 0.8 * Vec3::UnitX(), B3 = B0 - 0.7 * Vec3::UnitZ(),
               B2 = B1 - 0.7 * Vec3::UnitZ();
    for (const auto& [a, b] : std::vector<std::pair<Vec3, Vec3>>{{B0, B1}, {B1, B2}, {B2, B3}, {B3, B0}, {B0, T0}})
      demo::add_curve(sketch, make_line(a, b), Layer::scaffold);
    arc_id = demo::add_curve(sketch, arc, Layer::scaffold);
  }
};

bool has_curve_constraint(const Correction& r, CurveId id) {
  for (const Constraint& k : r.constraints)
    if (k.enforced && k.kind == ConstraintKind::point_on_curve)
      for (const ConstraintRef& ref : k.references)
        if (ref.kind == ConstraintRef::Kind::curve && ref.id == id) return true;
  return false;
}

LineCandidates candidates(const Scene& sc, const Stroke& stroke, const AnalyticParams& p) {
  const Scaffold s = build_scaffold(sc.sketch.network, Vec3::UnitY(), AnalyticParams{}.vanishing_merge);
  const Camera cam(sc.view);
  const Stroke2d s2 = make_stroke_2d(stroke, cam.dpi(), p);
  StrokeEnd ends[2];
  stroke_ends(cam, s2, ends);
  return collect_line_candidates(s, cam, s2, ends, p);
}

}  // namespace

TEST_CASE("curve_line_crossings: points on the curve whose projections lie on the line",
          "[analytic][curve_intersection]") {
  const Scene sc;
  const Camera cam(sc.view);
  const Vec2 x = cam.project(evaluate(sc.arc, 0.45)).value();
  const Vec2 a = cam.project(sc.T0).value();
  const auto hits = curve_line_crossings(sc.arc, cam, a, x, x, 1e6);
  REQUIRE(!hits.empty());
  const Vec2 n = Vec2(-(x - a).y(), (x - a).x()).normalized();
  bool found = false;
  for (const CurveCrossing& h : hits) {
    CHECK((h.point - evaluate(sc.arc, h.t)).norm() == 0.0);
    CHECK(std::abs(n.dot(cam.project(h.point).value() - a)) < 1e-6);
    if (std::abs(h.t - 0.45) < 1e-9) found = true;
  }
  CHECK(found);
  // Radius excludes crossings away from `near`; degenerate lines have none.
  CHECK(curve_line_crossings(sc.arc, cam, a, x, a, 5.0).empty());
  CHECK(curve_line_crossings(sc.arc, cam, x, x, x, 1e6).empty());
  // A line far from the projection (shifted along its normal) has none.
  CHECK(curve_line_crossings(sc.arc, cam, a + 2000 * n, x + 2000 * n, x, 1e6).empty());
}

TEST_CASE("a line stroke ending on an arc's projection ends on the 3D arc",
          "[analytic][curve_intersection]") {
  Scene sc;
  const Camera cam(sc.view);
  const Vec3 X = evaluate(sc.arc, 0.45);
  const Stroke stroke = demo::projected_stroke(100, sc.view, {sc.T0, X}, 0.3, 3);
  AnalyticParams p;
  AnalyticCorrector corrector{p};
  const Correction r = corrector.correct(stroke, sc.sketch);
  REQUIRE(r.error.empty());
  REQUIRE(r.edit.curves_added.size() == 1);
  const Curve& line = r.edit.curves_added[0].curve;
  REQUIRE(line.kind == CurveKind::line);
  CHECK((line.control_points.front() - sc.T0).norm() < 1e-9);
  CHECK(closest_point(sc.arc, line.control_points.back()).distance <= 1e-6);
  CHECK((line.control_points.back() - X).norm() < 0.02);  // near the drawn end (pixel noise)
  CHECK(has_curve_constraint(r, sc.arc_id));

  // The end's candidates hold the crossing, on the arc.
  const LineCandidates c = candidates(sc, stroke, p);
  int crossings = 0;
  for (const PointConstraint& pc : c.points[1])
    if (pc.type == PointConstraint::Type::curve_intersection) {
      ++crossings;
      CHECK(closest_point(sc.arc, pc.p).distance <= 1e-9);
    }
  CHECK(crossings == 1);

  // Without the constraint (f = 0) the same stroke does not end on the arc.
  AnalyticParams off = p;
  off.f_curve_intersection = 0.0;
  AnalyticCorrector without{off};
  const Correction r0 = without.correct(stroke, sc.sketch);
  REQUIRE(r0.edit.curves_added.size() == 1);
  CHECK(closest_point(sc.arc, r0.edit.curves_added[0].curve.control_points.back()).distance > 1e-4);
  CHECK(!has_curve_constraint(r0, sc.arc_id));
}

TEST_CASE("a line stroke ending far from an arc's projection gets no curve constraint",
          "[analytic][curve_intersection]") {
  Scene sc;
  const Camera cam(sc.view);
  const Vec3 Y = sc.T0 + Vec3(0, 0.35, 0);
  const Stroke stroke = demo::projected_stroke(100, sc.view, {sc.T0, Y}, 0.3, 3);
  // The end is farther from the arc's projection than any collection radius
  // (collect_factor·δ_max).
  AnalyticParams p;
  const Vec2 y = cam.project(Y).value();
  double nearest = 1e300;
  for (int i = 0; i <= 200; ++i)
    nearest = std::min(nearest, (cam.project(evaluate(sc.arc, i / 200.0)).value() - y).norm());
  REQUIRE(nearest > 2.0 * p.collect_factor * p.delta_max * cam.dpi());

  const LineCandidates c = candidates(sc, stroke, p);
  for (int e = 0; e < 2; ++e)
    for (const PointConstraint& pc : c.points[e]) CHECK(pc.type != PointConstraint::Type::curve_intersection);
  AnalyticCorrector corrector{p};
  const Correction r = corrector.correct(stroke, sc.sketch);
  REQUIRE(r.error.empty());
  REQUIRE(r.edit.curves_added.size() == 1);
  CHECK(!has_curve_constraint(r, sc.arc_id));
  CHECK(closest_point(sc.arc, r.edit.curves_added[0].curve.control_points.back()).distance > 0.1);
}
