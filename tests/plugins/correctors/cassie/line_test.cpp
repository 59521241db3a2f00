#include <catch2/catch.hpp>
#include <cmath>

#include "cassie_corrector.hpp"
#include "line_beautify.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "synthetic.hpp"

using namespace sketchlab;
using namespace sketchlab::cassie;

namespace {
Candidate at(double t, const Vec3& p) {
  Candidate c;
  c.kind = TargetKind::curve;
  c.t_stroke = t;
  c.target = p;
  return c;
}
}  // namespace

TEST_CASE("Appendix A: ends near constraints snap to them", "[cassie][line]") {
  const Vec3 a(0, 0, 0), b(1, 0.3, 0);
  const std::vector<Candidate> cs{at(0.01, {0.01, 0.02, 0}), at(0.5, {0.5, 0.2, 0}),
                                  at(0.99, {1.0, 0.31, 0.01})};
  const LineResult r = beautify_line(a, b, cs, 0.04, 0.5, false);
  CHECK(r.enforced == std::vector<int>{0, 2});  // the two nearest the ends, not the middle
  CHECK((r.a - cs[0].target).norm() == 0.0);
  CHECK((r.b - cs[2].target).norm() == 0.0);
}

TEST_CASE("Appendix A: two interior constraints project the ends", "[cassie][line]") {
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  const std::vector<Candidate> cs{at(0.3, {0.3, 0.02, 0}), at(0.7, {0.7, 0.03, 0})};
  const LineResult r = beautify_line(a, b, cs, 0.04, 0.5, false);
  const Curve l = make_line(r.a, r.b);
  for (const Candidate& c : cs) CHECK(closest_point(l, c.target).distance < 1e-12);
}

TEST_CASE("Appendix A: one interior constraint translates, free lines align to an axis",
          "[cassie][line]") {
  const Vec3 a(0, 0, 0), b(1, 0.1, 0);
  const std::vector<Candidate> one{at(0.5, {0.5, 0.08, 0.01})};
  const LineResult r = beautify_line(a, b, one, 0.04, 0.5236, true);
  CHECK(closest_point(make_line(r.a, r.b), one[0].target).distance < 1e-12);
  CHECK(r.axis == 0);
  CHECK(std::abs((r.b - r.a).normalized().x()) == Approx(1.0));
  const LineResult free = beautify_line(a, b, {}, 0.04, 0.5236, true);
  CHECK(free.axis == 0);
  CHECK((free.b - free.a).norm() == Approx((b - a).norm()));
  CHECK(((free.a + free.b) / 2 - (a + b) / 2).norm() < 1e-12);
}

TEST_CASE("A straight stroke ending near a curve becomes a line touching it", "[cassie][line]") {
  Sketch sketch;
  sketchlab::test::add_curve(sketch, make_line({0.3, -0.2, 0.1}, {0.3, 0.2, 0.1}));
  // Fast straight stroke, diagonal (no axis within θ), ending 1.5 cm short.
  const Stroke s = sketchlab::test::make_stroke(
      1, 30, [](double u) { return Vec3(-0.1 + 0.385 * u, -0.1 + 0.3 * u, 0.35 - 0.25 * u); }, 0.2);
  const Correction c = correct_stroke(s, sketch, CassieParams{});
  REQUIRE(c.error.empty());
  const Curve& out = c.edit.curves_added[0].curve;
  REQUIRE(out.kind == CurveKind::line);
  REQUIRE(c.edit.nodes_added.size() == 1);
  CHECK(closest_point(sketch.network.curves().at(1).curve, out.control_points.back()).distance < 1e-12);
  sketch.network.apply(c.edit);
}
