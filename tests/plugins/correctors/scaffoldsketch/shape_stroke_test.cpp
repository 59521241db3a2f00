// ScaffoldSketch §4.2: keypoints, tangents, MVC curves (eq. 8–9), straight strokes.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "mvc_curve.hpp"
#include "scaffold_line.hpp"
#include "shape_keypoints.hpp"
#include "shape_stroke.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "test_helpers.hpp"

using namespace sketchlab;
using namespace sketchlab::scaffoldsketch;
using namespace sketchlab::scaffoldsketch::test;

namespace {

// A square scaffold of side 0.4 in the plane y = 1, centred on (0, 1, 0).
void square_scaffold(Sketch& sketch) {
  const double r = 0.2;
  const Vec3 c0(r, 1, -r), c1(r, 1, r), c2(-r, 1, r), c3(-r, 1, -r);
  add_scaffold_line(sketch, c0, c1);
  add_scaffold_line(sketch, c1, c2);
  add_scaffold_line(sketch, c2, c3);
  add_scaffold_line(sketch, c3, c0);
}

double curvature(const Curve& c, double t) {
  const Vec3 d1 = derivative(c, t), d2 = second_derivative(c, t);
  return d1.cross(d2).norm() / std::pow(d1.norm(), 3);
}

}  // namespace

TEST_CASE("Menger curvature (eq. 8) and its gradient", "[scaffoldsketch]") {
  const double r = 0.25;
  const Vec3 a(r, 0, 0), b(r * std::cos(0.4), r * std::sin(0.4), 0), c(r * std::cos(1.1), r * std::sin(1.1), 0);
  Mat3 g;
  CHECK(menger_curvature(a, b, c, &g) == Approx(1 / r));
  for (int p = 0; p < 3; ++p)
    for (int k = 0; k < 3; ++k) {
      Vec3 pts[3] = {a + Vec3(0.01, 0.02, 0.03), b, c};
      const double h = 1e-7;
      pts[p](k) += h;
      const double fp = menger_curvature(pts[0], pts[1], pts[2]);
      pts[p](k) -= 2 * h;
      const double fm = menger_curvature(pts[0], pts[1], pts[2]);
      Mat3 g2;
      menger_curvature(a + Vec3(0.01, 0.02, 0.03), b, c, &g2);
      CHECK(g2(k, p) == Approx((fp - fm) / (2 * h)).margin(1e-5));
    }
  CHECK(menger_curvature(a, a, c, &g) == 0.0);
  CHECK(g.allFinite());
  CHECK(menger_curvature(a, 0.5 * (a + c), c, &g) == 0.0);
  CHECK(g.allFinite());
}

TEST_CASE("a shape stroke around a square scaffold becomes a circle (Figure 5)", "[scaffoldsketch]") {
  Sketch sketch;
  square_scaffold(sketch);
  // Hand-drawn circle through the four side midpoints, starting at (0.2, 1, 0).
  std::vector<Vec3> pts;
  const int n = 300;
  for (int i = 0; i <= n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    const double wobble = 0.006 * std::sin(5 * a) + 0.002 * std::cos(11 * a);
    const double r = 0.2 + wobble;
    pts.push_back(Vec3(r * std::cos(a), 1 + 0.004 * std::sin(3 * a), r * std::sin(a)));
  }
  const Stroke s = polyline_stroke(50, pts, Layer::shape);
  const Correction c = correct_shape_stroke(s, sketch, ShapeParams{}, 1e-6, PreprocessParams{});
  REQUIRE(c.error.empty());
  REQUIRE(c.edit.curves_added.size() == 1);
  const Curve& curve = c.edit.curves_added[0].curve;
  CHECK(c.stats.outcomes.at("mode") == mode_shape_curve);
  CHECK(c.stats.extra.at("keypoints") == 5);
  CHECK(curve.closed);
  REQUIRE(curve.segment_count() == 4);
  // Through the midpoints, tangent to the sides.
  for (int k = 0; k < 4; ++k) {
    const Vec3 p = evaluate(curve, k);
    CHECK(std::abs(p.y() - 1) < 1e-12);
    CHECK(std::abs(std::hypot(p.x(), p.z()) - 0.2) < 1e-12);
    const Vec3 radial = Vec3(p.x(), 0, p.z()).normalized();
    CHECK(std::abs(tangent(curve, k).dot(radial)) < 1e-12);
  }
  // Curvature nearly constant: a circle within what cubics can do.
  std::vector<double> kappa;
  double radial_error = 0;
  for (int i = 0; i < 400; ++i) {
    const double t = 4.0 * (i + 0.5) / 400;
    kappa.push_back(curvature(curve, t));
    const Vec3 p = evaluate(curve, t);
    radial_error = std::max(radial_error, std::abs(std::hypot(p.x(), p.z()) - 0.2));
  }
  double mean = 0;
  for (double k : kappa) mean += k;
  mean /= static_cast<double>(kappa.size());
  double var = 0;
  for (double k : kappa) var += (k - mean) * (k - mean);
  const double cv = std::sqrt(var / static_cast<double>(kappa.size())) / mean;
  CHECK(mean == Approx(5.0).epsilon(0.01));
  CHECK(cv < 0.01);
  CHECK(radial_error < 0.001 * 0.2);
  CHECK(c.stats.extra.at("objective") < c.stats.extra.at("initial_objective"));
  // A node at every midpoint joins the circle to the side.
  CHECK(c.edit.nodes_added.size() == 4);
}

TEST_CASE("a roughly straight shape stroke becomes an exact line", "[scaffoldsketch]") {
  Sketch sketch;
  square_scaffold(sketch);
  const Vec3 p(0.2, 1, 0.2), q(-0.2, 1, -0.2);  // diagonal corners
  std::vector<Vec3> pts;
  for (int i = 0; i <= 80; ++i) {
    const double u = i / 80.0;
    pts.push_back(p + Vec3(0.008, 0.01, -0.006) + (q - p) * u +
                  Vec3(0.012 * std::sin(3.1 * u), 0.006 * std::sin(7 * u), 0.0));
  }
  const Correction c =
      correct_shape_stroke(polyline_stroke(60, pts, Layer::shape), sketch, ShapeParams{}, 1e-6,
                           PreprocessParams{});
  REQUIRE(c.error.empty());
  REQUIRE(c.edit.curves_added.size() == 1);
  const Curve& line = c.edit.curves_added[0].curve;
  CHECK(line.kind == CurveKind::line);
  CHECK(line.control_points.front() == p);
  CHECK(line.control_points.back() == q);
  CHECK(c.stats.outcomes.at("mode") == mode_shape_line);
}

TEST_CASE("a bent shape stroke is not straightened", "[scaffoldsketch]") {
  Sketch sketch;
  square_scaffold(sketch);
  // Quarter arc from the midpoint of one side to the next.
  std::vector<Vec3> pts;
  for (int i = 0; i <= 60; ++i) {
    const double a = 0.5 * std::numbers::pi * i / 60;
    pts.push_back(Vec3(0.2 * std::cos(a), 1, 0.2 * std::sin(a)));
  }
  const Correction c =
      correct_shape_stroke(polyline_stroke(61, pts, Layer::shape), sketch, ShapeParams{}, 1e-6,
                           PreprocessParams{});
  REQUIRE(c.error.empty());
  const Curve& arc = c.edit.curves_added.at(0).curve;
  CHECK(arc.kind == CurveKind::bezier);
  REQUIRE(arc.segment_count() == 1);
  // Symmetric MVC arc: equal tangent magnitudes, close to the circle.
  const double x1 = (arc.control_points[1] - arc.control_points[0]).norm();
  const double x2 = (arc.control_points[3] - arc.control_points[2]).norm();
  CHECK(x1 == Approx(x2).epsilon(1e-4));
  CHECK(x1 / 0.2 == Approx(0.5523).epsilon(0.02));
}

TEST_CASE("a straight shape stroke: the paper's line or the authors' polyline (straight_shape)",
          "[scaffoldsketch]") {
  // Three keypoints, the middle one 1.2 cm off the line through the others.
  Sketch sketch;
  const Vec3 p(0, 1, 0), m(0.2, 1.012, 0), q(0.4, 1, 0);
  for (const Vec3& k : {p, m, q}) add_scaffold_line(sketch, k, k + Vec3(0, 0, 0.3));
  std::vector<Vec3> pts;
  for (int i = 0; i <= 80; ++i) {
    const double u = i / 80.0;
    pts.push_back(p + (q - p) * u + Vec3(0, 0.006 * std::sin(std::numbers::pi * u), 0.002));
  }
  const Stroke s = polyline_stroke(70, pts, Layer::shape);
  const Correction line = correct_shape_stroke(s, sketch, ShapeParams{}, 1e-6, PreprocessParams{});
  REQUIRE(line.error.empty());
  CHECK(line.stats.outcomes.at("mode") == mode_shape_line);
  CHECK(line.stats.extra.at("keypoints") == 3);
  const Curve& exact = line.edit.curves_added.at(0).curve;
  CHECK(exact.kind == CurveKind::line);
  CHECK(exact.control_points.front() == p);
  CHECK(exact.control_points.back() == q);

  ShapeParams authors;
  authors.straight_shape = StraightShape::polyline;
  const Correction poly = correct_shape_stroke(s, sketch, authors, 1e-6, PreprocessParams{});
  REQUIRE(poly.error.empty());
  CHECK(poly.stats.outcomes.at("mode") == mode_shape_line);
  const Curve& c = poly.edit.curves_added.at(0).curve;
  REQUIRE(c.segment_count() == 2);
  CHECK((evaluate(c, 0) - p).norm() < 1e-12);
  CHECK((evaluate(c, 1) - m).norm() < 1e-12);
  CHECK((evaluate(c, 2) - q).norm() < 1e-12);
  for (int k = 0; k < 2; ++k) {  // each segment straight
    const Vec3 u = (evaluate(c, k + 1) - evaluate(c, k)).normalized();
    for (int j = 1; j < 10; ++j) {
      const Vec3 x = evaluate(c, k + j / 10.0) - evaluate(c, k);
      CHECK((x - u * u.dot(x)).norm() < 1e-12);
    }
  }
  CHECK(poly.edit.nodes_added.size() == 3);  // joined at every keypoint
}

TEST_CASE("a keypoint's tangent from its closest sample or the best of its run (tangent_sample)",
          "[scaffoldsketch]") {
  // The stroke runs along a scaffold line into its end keypoint K and turns
  // 40° there: at the sample closest to K the forward difference is 40° off
  // the line (> 25°, no snap), the samples before K run along it.
  Sketch sketch;
  const Vec3 k(0, 1, 0);
  const CurveId along = add_scaffold_line(sketch, k, Vec3(0.3, 1, 0));
  const Vec3 turned(std::cos(40 * degrees), std::sin(40 * degrees), 0);
  std::vector<Vec3> samples;
  for (int i = -20; i <= 0; ++i) samples.push_back(k + Vec3(0.01 * i, 0, 0));
  for (int i = 1; i <= 20; ++i) samples.push_back(k + 0.01 * i * turned);
  const ShapeKeypoints closest = select_shape_keypoints(samples, sketch.network, ShapeParams{}, 1.0);
  REQUIRE(closest.points.size() == 1);
  CHECK(closest.points[0] == k);
  CHECK(closest.tangent_curve[0] == 0);  // the stroke's own direction
  CHECK(closest.tangents[0].dot(Vec3::UnitX()) < std::cos(5 * degrees));

  ShapeParams authors;
  authors.tangent_sample = TangentSample::best;
  const ShapeKeypoints best = select_shape_keypoints(samples, sketch.network, authors, 1.0);
  REQUIRE(best.points.size() == 1);
  CHECK(best.tangent_curve[0] == along);
  CHECK((best.tangents[0] - Vec3::UnitX()).norm() < 1e-12);
}
