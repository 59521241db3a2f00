// Lines (CASSIE app item 17; thesis Appendix A): exact synthetic cases.
#include <catch2/catch.hpp>
#include <cmath>

#include "cassie_corrector.hpp"
#include "line_beautify.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "synthetic.hpp"

using namespace sketchlab;
using namespace sketchlab::cassie;

namespace {

Candidate at(const Vec3& p, TargetKind kind = TargetKind::curve) {
  Candidate c;
  c.kind = kind;
  c.target = p;
  return c;
}

constexpr double snap = 0.04, keep = 0.004, theta = 0.5235987755982988;  // 2δ, 0.2δ, π/6

double off_line(const LineResult& r, const Vec3& p) { return closest_point(make_line(r.a, r.b), p).distance; }

}  // namespace

TEST_CASE("Lines: with more than two constraints, the first detected and the farthest from it",
          "[cassie][line]") {
  const Vec3 a(0, 0, 0), b(1, 0.3, 0);
  // Detection order: the middle one first, then one near b, then one near a.
  const std::vector<Candidate> cs{at({0.5, 0.16, 0}), at({0.98, 0.3, 0.01}), at({0.01, 0.02, 0})};
  const LineResult r = beautify_line(a, b, cs, snap, keep, theta, false);
  // Farthest from the first (0.5, 0.16): (0.98, 0.3) is 0.50 away, (0.01, 0.02) 0.51.
  CHECK(r.used == std::vector<int>{0, 2});
  // (0.01, 0.02) snaps end a (within 2δ); the middle one is beyond neither end
  // and 0.3 m from b: b is projected onto the line from the new a through it.
  CHECK(r.a == cs[2].target);
  CHECK(off_line(r, cs[0].target) < 1e-12);
  CHECK(r.enforced == std::vector<int>{0, 2});
}

TEST_CASE("Lines: an end snaps to its constraint within 2δ or beyond the end", "[cassie][line]") {
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  // 3 cm before a (beyond it) and 3.9 cm from b: both snap.
  const std::vector<Candidate> cs{at({-0.03, 0.001, 0}), at({0.97, 0.025, 0})};
  const LineResult r = beautify_line(a, b, cs, snap, keep, theta, false);
  CHECK(r.a == cs[0].target);
  CHECK(r.b == cs[1].target);
  CHECK(r.enforced.size() == 2);
}

TEST_CASE("Lines: two constraints within 2δ of one end snap it and leave the other end as drawn",
          "[cassie][line]") {
  // vintage_car stroke 44: a 1.1 m line whose two constraints (2 cm apart,
  // across the stroke) both lie at its start. Matched along the line, the
  // second would take end b, which would be projected onto the line through
  // the two: a 3 cm line across the stroke, 1.07 m from where it was drawn.
  const Vec3 a(0, 0, 0), b(0, 0, 1.1);
  const std::vector<Candidate> cs{at({0.02, 0.01, -0.01}), at({0.0, 0.03, 0.012})};
  const LineResult r = beautify_line(a, b, cs, snap, keep, theta, false);
  CHECK(r.used == std::vector<int>{0, 1});
  CHECK(r.a == cs[0].target);  // the first detected takes the end
  CHECK(r.b == b);
  CHECK(r.enforced == std::vector<int>{0});
  // Near both ends (a short line): each keeps its own end.
  const Vec3 c(0.05, 0, 0);
  const std::vector<Candidate> ds{at({0.052, 0.01, 0}), at({0.001, 0.01, 0})};
  const LineResult s = beautify_line(a, c, ds, snap, keep, theta, false);
  CHECK(s.a == ds[1].target);
  CHECK(s.b == ds[0].target);
}

TEST_CASE("Lines: interior constraints project a onto the line to b, then b", "[cassie][line]") {
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  const Vec3 p(0.3, 0.02, 0), q(0.7, 0.03, 0.01);
  const LineResult r = beautify_line(a, b, {at(p), at(q)}, snap, keep, theta, false);
  // a on the line p–b (b as drawn), then b on the line from the new a through q.
  const Vec3 u = (b - p).normalized();
  CHECK((r.a - (p + (a - p).dot(u) * u)).norm() < 1e-12);
  const Vec3 w = (q - r.a).normalized();
  CHECK((r.b - (r.a + (b - r.a).dot(w) * w)).norm() < 1e-12);
  CHECK(off_line(r, q) < 1e-12);
  // p is off the final line by more than 0.2δ: no node there.
  CHECK(off_line(r, p) > keep);
  CHECK(r.enforced == std::vector<int>{1});
}

TEST_CASE("Lines: one constraint away from both ends moves the line across onto it", "[cassie][line]") {
  // CASSIE's vintage_car lines 40, 54, 434 and 632: both ends move by the
  // same offset, the direction is kept (the reference's rule turned the line
  // about b instead).
  const Vec3 a(0, 0, 0), b(1, 0.2, 0);
  const Vec3 p(0.6, 0.15, 0.02);  // 3.1 cm off the line, 0.44 m from b
  const LineResult r = beautify_line(a, b, {at(p)}, snap, keep, theta, false);
  const Vec3 offset = r.a - a;
  CHECK((r.b - b - offset).norm() < 1e-12);
  CHECK(offset.dot(b - a) == Approx(0.0).margin(1e-12));
  CHECK(off_line(r, p) < 1e-12);
  CHECK(r.enforced == std::vector<int>{0});
  // Matched to b (nearer along the line) it moves the same way.
  const LineResult s = beautify_line(b, a, {at(p)}, snap, keep, theta, false);
  CHECK((s.a - r.b).norm() < 1e-12);
  CHECK((s.b - r.a).norm() < 1e-12);
}

TEST_CASE("Lines: of two constraints closer than 0.2δ one is kept, an intersection first",
          "[cassie][line]") {
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  const std::vector<Candidate> cs{at({0.999, 0.01, 0}, TargetKind::grid), at({1.001, 0.012, 0})};
  const LineResult r = beautify_line(a, b, cs, snap, keep, theta, false);
  CHECK(r.used == std::vector<int>{1});
  CHECK(r.b == cs[1].target);
}

TEST_CASE("Lines: axis snap about the start, or the snapped end, within 2δ", "[cassie][line]") {
  SECTION("no constraint: rotated about a") {
    const Vec3 a(0.1, 0.2, 0.3), b(0.1 + 0.3, 0.2 + 0.02, 0.3);  // 3.8° off x, b moves 2 cm
    const LineResult r = beautify_line(a, b, {}, snap, keep, theta, true);
    CHECK(r.axis == 0);
    CHECK(r.a == a);
    CHECK((r.b - (a + (b - a).norm() * Vec3::UnitX())).norm() < 1e-12);  // length kept
  }
  SECTION("no constraint: the far end would move more than 2δ") {
    const Vec3 a(0, 0, 0), b(1.0, 0.2, 0);  // 11° off x on a 1 m line: b moves 19 cm
    const LineResult r = beautify_line(a, b, {}, snap, keep, theta, true);
    CHECK(r.axis == -1);
    CHECK(r.b == b);
  }
  SECTION("one constraint: about the snapped end") {
    const Vec3 a(0, 0, 0), b(0.02, 0.3, 0);  // along y
    const Vec3 p(0.005, 0.31, 0.01);           // near b
    const LineResult r = beautify_line(a, b, {at(p)}, snap, keep, theta, true);
    CHECK(r.axis == 1);
    CHECK(r.b == p);
    CHECK(std::abs((r.b - r.a).normalized().y()) == Approx(1.0));
    CHECK(r.enforced == std::vector<int>{0});
  }
  SECTION("two constraints: no axis snap") {
    const Vec3 a(0, 0, 0), b(0.3, 0.01, 0);
    const LineResult r =
        beautify_line(a, b, {at({0.001, 0.002, 0}), at({0.3, 0.015, 0})}, snap, keep, theta, true);
    CHECK(r.axis == -1);
  }
}

TEST_CASE("A straight stroke ending near a curve becomes a line touching it", "[cassie][line]") {
  Sketch sketch;
  sketchlab::test::add_curve(sketch, make_line({0.3, -0.2, 0.1}, {0.3, 0.2, 0.1}));
  // Fast (0.52 m/s) straight stroke, diagonal (no axis within θ), ending 1 cm
  // short: the last brush step (item 6: none at the end) touches the curve.
  const Stroke s = sketchlab::test::make_stroke(
      1, 30, [](double u) { return Vec3(-0.1 + 0.39 * u, -0.1 + 0.3 * u, 0.35 - 0.25 * u); }, 1.0);
  const Correction c = correct_stroke(s, sketch, CassieParams{});
  REQUIRE(c.error.empty());
  const Curve& out = c.edit.curves_added[0].curve;
  REQUIRE(out.kind == CurveKind::line);
  REQUIRE(c.edit.nodes_added.size() == 1);
  CHECK(closest_point(sketch.network.curves().at(1).curve, out.control_points.back()).distance < 1e-12);
  sketch.network.apply(c.edit);
}
