// A stroke's ends (CASSIE app items 9, 10, 16): the overlap cut before
// solving, closure as a hard constraint, trimming dangling ends after.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "cassie_corrector.hpp"
#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "stroke_ends.hpp"
#include "synthetic.hpp"

using namespace sketchlab;
using namespace sketchlab::cassie;
using sketchlab::test::add_curve;
using sketchlab::test::find_kind;
using sketchlab::test::make_stroke;
using sketchlab::test::straight;

namespace {

Candidate on(const Curve& stroke, double t, CurveId curve, double t_curve, const Vec3& target) {
  Candidate c;
  c.kind = TargetKind::curve;
  c.curve = curve;
  c.t_curve = t_curve;
  c.target = target;
  c.t_stroke = t;
  c.distance = (evaluate(stroke, t) - target).norm();
  return c;
}

}  // namespace

TEST_CASE("Item 9: an end running along the curve it meets is cut there", "[cassie][ends]") {
  Sketch sketch;
  add_curve(sketch, make_line({-0.5, 0.003, 0}, {0.5, 0.003, 0}));  // curve 1, along x
  add_curve(sketch, make_line({0.25, -0.5, 0}, {0.25, 0.5, 0}));    // curve 2, along y
  const Curve stroke = straight({0, 0, 0}, {0.3, 0, 0}, 3);
  SECTION("parallel, within 2δ of the start: cut") {
    std::vector<Candidate> c{on(stroke, 0.3, 1, 0.53, {0.03, 0.003, 0})};
    const Curve out = cut_overlaps(stroke, c, sketch.network, 0.04, std::numbers::pi / 6);
    CHECK((out.control_points.front() - Vec3(0.03, 0, 0)).norm() < 1e-12);
    CHECK((out.control_points.back() - Vec3(0.3, 0, 0)).norm() < 1e-12);
    REQUIRE(c.size() == 1);
    CHECK(c[0].t_stroke == Approx(0.0).margin(1e-9));  // now at the new start
  }
  SECTION("crossing (perpendicular tangents): no cut") {
    std::vector<Candidate> c{on(stroke, 2.5, 2, 0.5, {0.25, 0, 0})};
    const Curve out = cut_overlaps(stroke, c, sketch.network, 0.06, std::numbers::pi / 6);
    CHECK(out.control_points == stroke.control_points);
  }
  SECTION("parallel but farther than 2δ from the end: no cut") {
    std::vector<Candidate> c{on(stroke, 0.6, 1, 0.56, {0.06, 0.003, 0})};
    const Curve out = cut_overlaps(stroke, c, sketch.network, 0.04, std::numbers::pi / 6);
    CHECK(out.control_points == stroke.control_points);
  }
  SECTION("a grid point is not an intersection: no cut") {
    std::vector<Candidate> c{on(stroke, 2.8, 1, 0.78, {0.28, 0.003, 0})};
    c[0].kind = TargetKind::grid;
    const Curve out = cut_overlaps(stroke, c, sketch.network, 0.04, std::numbers::pi / 6);
    CHECK(out.control_points == stroke.control_points);
  }
  SECTION("the last constraint cuts the end; constraints past it are dropped") {
    std::vector<Candidate> c{on(stroke, 1.5, 2, 0.5, {0.15, 0, 0}), on(stroke, 2.7, 1, 0.77, {0.27, 0.003, 0})};
    const Curve out = cut_overlaps(stroke, c, sketch.network, 0.04, std::numbers::pi / 6);
    CHECK((out.control_points.back() - Vec3(0.27, 0, 0)).norm() < 1e-12);
    CHECK(c.size() == 2);
  }
}

TEST_CASE("Item 16: a short dangling piece beyond the last intersection is trimmed", "[cassie][ends]") {
  SECTION("unit: under 15 % and 3δ") {
    Curve c = straight({0, 0, 0}, {0.5, 0, 0}, 10);  // 5 cm per segment
    // Enforced at joints 1 (5 cm from the start) and 8 (10 cm from the end).
    const int removed = trim_dangling(c, {1, 8}, 0.15, 0.06);
    CHECK(removed == 1);
    CHECK((c.control_points.front() - Vec3(0.05, 0, 0)).norm() < 1e-12);
    // 10 cm is more than 3δ: the end stays.
    CHECK((c.control_points.back() - Vec3(0.5, 0, 0)).norm() < 1e-12);
    CHECK(c.segment_count() == 9);
  }
  SECTION("a stroke overshooting a crossing by 3.5 cm ends on it") {
    Sketch sketch;
    add_curve(sketch, make_line({0.2, -0.2, 0.005}, {0.2, 0.2, 0.005}));
    const Stroke s = make_stroke(1, 80, [](double u) { return Vec3(-0.2 + 0.435 * u, 0.03 * std::sin(3.14159 * u), 0); }, 2.0);
    const Correction c = correct_stroke(s, sketch, CassieParams{});
    REQUIRE(c.error.empty());
    const Curve& out = c.edit.curves_added[0].curve;
    REQUIRE(c.edit.nodes_added.size() == 1);
    // The end is the intersection (within the old line's 5 mm offset), not
    // the raw end 3.5 cm past it.
    CHECK(closest_point(sketch.network.curves().at(1).curve, out.control_points.back()).distance < 1e-9);
    CHECK(c.edit.nodes_added[0].incidences[0].t == Approx(out.t_max()));
    CassieParams keep;
    keep.trim_dangling = false;
    const Correction kept = correct_stroke(s, sketch, keep);  // kept alive: a reference into it is read below
    CHECK(kept.edit.curves_added[0].curve.control_points.back().x() > 0.23);
  }
}

TEST_CASE("Item 10: closure is a hard constraint in every subset, skipped when both ends are taken",
          "[cassie][ends]") {
  // 350° of a 15 cm circle: the ends are 2.6 cm apart (< 2δ).
  auto loop = [](double u) {
    const double a = (350.0 / 360.0) * 2 * std::numbers::pi * u;
    return Vec3(0.15 * std::cos(a), 0.15 * std::sin(a), 0.0);
  };
  const Stroke s = make_stroke(4, 150, loop, 2.0);
  SECTION("with one end on a curve, both ends go there") {
    Sketch sketch;
    // Its end (0.15, 0, 0.01) is 1 cm from the stroke's start (0.15, 0, 0), 2.8 cm from its end.
    add_curve(sketch, make_line({0.15, 0.0, 0.01}, {0.15, 0.2, 0.01}));
    const Correction c = correct_stroke(s, sketch, CassieParams{});
    REQUIRE(c.error.empty());
    const Curve& out = c.edit.curves_added[0].curve;
    CHECK(out.closed);
    CHECK(out.control_points.front() == out.control_points.back());
    const Constraint* k = find_kind(c, ConstraintKind::closure);
    REQUIRE(k);
    CHECK(k->enforced);
    CHECK(k->weight == 0.0);  // no weight: not part of E_connectivity
    CHECK(closest_point(sketch.network.curves().at(1).curve, out.control_points.front()).distance < 1e-9);
  }
  SECTION("both ends on curves: no closure") {
    Sketch sketch;
    // Passes 1.2 cm from the start (0.15, 0) and from the end (0.148, -0.026).
    add_curve(sketch, make_line({0.15, -0.2, 0.012}, {0.15, 0.0, 0.012}));
    const Correction c = correct_stroke(s, sketch, CassieParams{});
    REQUIRE(c.error.empty());
    CHECK(find_kind(c, ConstraintKind::closure) == nullptr);
    CHECK_FALSE(c.edit.curves_added[0].curve.closed);
  }
  SECTION("a single Bézier does not close") {
    // A 3 cm hairpin whose ends coincide, fitted by one cubic.
    const Stroke hairpin = make_stroke(5, 40, [](double u) {
      return Vec3(0.03 * std::sin(std::numbers::pi * u), 0.01 * std::sin(2 * std::numbers::pi * u), 0.0);
    }, 1.0);
    const Correction c = correct_stroke(hairpin, Sketch{}, CassieParams{});
    REQUIRE(c.error.empty());
    REQUIRE(c.edit.curves_added[0].curve.segment_count() == 1);
    CHECK(find_kind(c, ConstraintKind::closure) == nullptr);
    CHECK_FALSE(c.edit.curves_added[0].curve.closed);
  }
}

// CASSIE's structured curves never reach the last raw sample (README, "Where
// this differs from the reference"): by default the curve ends 0.02 s of
// hand motion before it (`trim_last_end`), the first end at the first
// sample; `trim_last_end=false` keeps item 1 as stated.
TEST_CASE("Item 1: the last end is 0.02 s of hand motion before the last sample", "[cassie][ends]") {
  const Params defaults = validate_params(param_specs(), {});
  CHECK(params_from(defaults).preprocess.app_trim_last_end);
  CHECK_FALSE(params_from(validate_params(param_specs(), {{"trim_last_end", ParamValue{false}}}))
                  .preprocess.app_trim_last_end);

  // 41 samples over 1 s of a circular arc 0.64 m long, at constant speed:
  // 0.02 s is four fifths of the last step, so the curve ends a fifth of the
  // way from sample 39 to sample 40.
  const Stroke s = make_stroke(3, 41, [](double u) {
    const double a = 1.6 * u - 0.8;
    return Vec3(0.4 * std::sin(a), 0.4 * (1 - std::cos(a)), 0.1);
  });
  const Vec3 a = s.samples[39].position, b = s.samples[40].position;
  const Vec3 expected = a + 0.2 * (b - a);
  CassieParams p;
  p.planarity = false;
  const Correction trimmed = correct_stroke(s, Sketch{}, p);
  REQUIRE(trimmed.edit.curves_added.size() == 1);
  const Curve& c = trimmed.edit.curves_added[0].curve;
  CHECK((c.control_points.back() - expected).norm() < 1e-12);
  CHECK((c.control_points.front() - s.samples.front().position).norm() < 1e-12);

  p.preprocess.app_trim_last_end = false;
  const Correction kept = correct_stroke(s, Sketch{}, p);
  REQUIRE(kept.edit.curves_added.size() == 1);
  CHECK((kept.edit.curves_added[0].curve.control_points.back() - b).norm() < 1e-12);
}
