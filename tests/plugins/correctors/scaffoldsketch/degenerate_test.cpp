// Degenerate input: clear results, never NaN.
#include <catch2/catch.hpp>

#include <cmath>

#include "irls_solver.hpp"
#include "mvc_curve.hpp"
#include "scaffold_line.hpp"
#include "scaffoldsketch_corrector.hpp"
#include "shape_stroke.hpp"
#include "test_helpers.hpp"

using namespace sketchlab;
using namespace sketchlab::scaffoldsketch;
using namespace sketchlab::scaffoldsketch::test;

namespace {

bool finite_edit(const Edit& e) {
  for (const auto& c : e.curves_added) {
    for (const Vec3& p : c.curve.control_points)
      if (!p.allFinite()) return false;
    for (const Keypoint& k : c.keypoints)
      if (!k.position.allFinite() || !std::isfinite(k.t)) return false;
  }
  for (const auto& n : e.nodes_added)
    if (!n.position.allFinite()) return false;
  return true;
}

bool finite_constraints(const Correction& c) {
  for (const Constraint& k : c.constraints)
    if (!std::isfinite(k.residual) || !std::isfinite(k.weight) || !k.target.allFinite())
      return false;
  for (const auto& [name, v] : c.stats.extra)
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

TEST_CASE("zero-length strokes", "[scaffoldsketch]") {
  Sketch sketch;
  add_scaffold_line(sketch, Vec3(0, 1, 0), Vec3(0.5, 1, 0));
  ScaffoldSketchCorrector corrector{ScaffoldParams{}, ShapeParams{}};
  const Vec3 p(0.2, 1.001, 0);
  for (Layer layer : {Layer::scaffold, Layer::automatic}) {
    // A tap on a line: a tick there.
    const Correction tap = corrector.correct(straight_stroke(1, p, p, layer, 5), sketch);
    CHECK(tap.error.empty());
    REQUIRE(tap.edit.curves_replaced.size() == 1);
    CHECK(tap.edit.curves_replaced[0].keypoints.back().kind == Keypoint::Kind::tick);
    // A tap in empty space: nothing, with a reason in the stats.
    const Correction none = corrector.correct(straight_stroke(2, Vec3(5, 5, 5), Vec3(5, 5, 5), layer, 5), sketch);
    CHECK(none.error.empty());
    CHECK(none.edit.empty());
    CHECK(none.stats.extra.at("ignored") == 1);
  }
  // A zero-length shape stroke: an error naming the stroke.
  const Correction shape = corrector.correct(straight_stroke(3, p, p, Layer::shape, 5), sketch);
  CHECK(shape.error.find("stroke 3") != std::string::npos);
  CHECK(shape.edit.empty());
  CHECK(finite_constraints(shape));
}

TEST_CASE("duplicate samples", "[scaffoldsketch]") {
  Sketch sketch;
  add_scaffold_line(sketch, Vec3(0, 1, 0), Vec3(0.3, 1, 0));
  ScaffoldSketchCorrector corrector{ScaffoldParams{}, ShapeParams{}};
  for (Layer layer : {Layer::scaffold, Layer::shape, Layer::automatic}) {
    Stroke s = straight_stroke(4, Vec3(0.31, 1.0, 0.0), Vec3(0.3, 1.31, 0.0), layer, 20);
    std::vector<Sample> doubled;
    for (const Sample& x : s.samples) {
      doubled.push_back(x);
      doubled.push_back(x);
    }
    s.samples = doubled;
    const Correction c = corrector.correct(s, sketch);
    CHECK(c.error.empty());
    REQUIRE(c.edit.curves_added.size() == 1);
    CHECK(finite_edit(c.edit));
    CHECK(finite_constraints(c));
  }
}

TEST_CASE("collinear everything", "[scaffoldsketch]") {
  Sketch sketch;
  add_scaffold_line(sketch, Vec3(0, 1, 0), Vec3(0.4, 1, 0));
  ScaffoldSketchCorrector corrector{ScaffoldParams{}, ShapeParams{}};
  // A shape stroke along the line through its three keypoints: the line itself.
  const Correction c =
      corrector.correct(straight_stroke(5, Vec3(0, 1, 0), Vec3(0.4, 1, 0), Layer::shape, 40), sketch);
  REQUIRE(c.error.empty());
  const Curve& line = c.edit.curves_added.at(0).curve;
  CHECK(line.kind == CurveKind::line);
  CHECK(line.control_points.front() == Vec3(0, 1, 0));
  CHECK(line.control_points.back() == Vec3(0.4, 1, 0));
  // A scaffold stroke drawn exactly over it: everything satisfied from the start.
  const Correction again =
      corrector.correct(straight_stroke(6, Vec3(0, 1, 0), Vec3(0.4, 1, 0), Layer::scaffold), sketch);
  REQUIRE(again.error.empty());
  CHECK(finite_edit(again.edit));
  CHECK(finite_constraints(again));
  CHECK(again.edit.curves_added.at(0).curve.control_points.front() == Vec3(0, 1, 0));
  // MVC through collinear keypoints with collinear tangents: a straight curve.
  const std::vector<Vec3> q{Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0.3, 0, 0)};
  const std::vector<Vec3> d(3, Vec3::UnitX());
  const MvcResult mvc = fit_mvc_curve(q, d, false, ShapeParams{});
  CHECK(mvc.objective == Approx(0.0).margin(1e-20));
  for (const Vec3& p : mvc.curve.control_points) {
    CHECK(p.allFinite());
    CHECK(std::abs(p.y()) + std::abs(p.z()) < 1e-15);
  }
  // Bad MVC input is an error, not NaN.
  CHECK_THROWS_AS(fit_mvc_curve({q[0], q[0]}, {d[0], d[0]}, false, ShapeParams{}),
                  std::invalid_argument);
  CHECK_THROWS_AS(fit_mvc_curve({q[0]}, {d[0]}, false, ShapeParams{}), std::invalid_argument);
  // IRLS with nothing to satisfy leaves the line alone.
  const IrlsResult r = solve_irls({}, Vec3(0, 0, 0), Vec3(1, 0, 0), IrlsOptions{});
  CHECK(r.a == Vec3(0, 0, 0));
  CHECK(r.b == Vec3(1, 0, 0));
}

TEST_CASE("a shape stroke with fewer than two keypoints falls back to the freehand fit",
          "[scaffoldsketch]") {
  Sketch sketch;
  std::vector<Vec3> pts;
  for (int i = 0; i <= 50; ++i)
    pts.push_back(Vec3(0.01 * i, 1 + 0.1 * std::sin(0.1 * i), 0));
  ScaffoldSketchCorrector corrector{ScaffoldParams{}, ShapeParams{}};
  const Correction c = corrector.correct(polyline_stroke(7, pts, Layer::shape), sketch);
  REQUIRE(c.error.empty());
  REQUIRE(c.edit.curves_added.size() == 1);
  CHECK(c.edit.curves_added[0].layer == Layer::shape);
  CHECK(c.stats.outcomes.at("mode") == mode_shape_fallback);
  CHECK(finite_edit(c.edit));
}
