#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "kernel/geometry/random_curves.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"

using namespace sketchlab;

namespace {

double dense_distance(const Curve& c, const Vec3& p, int samples) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= samples; ++i) {
    const double t = c.t_max() * static_cast<double>(i) / samples;
    best = std::min(best, (evaluate(c, t) - p).norm());
  }
  return best;
}

}  // namespace

TEST_CASE("closest_point is never worse than dense sampling on random curves",
          "[geometry][closest_point]") {
  std::mt19937_64 rng(20240611);
  for (int trial = 0; trial < 60; ++trial) {
    const int k = 1 + trial % 4;
    const Curve c = test::random_curve(rng, k);
    for (int q = 0; q < 5; ++q) {
      const Vec3 p = test::random_point(rng, 1.5);
      const ClosestPoint cp = closest_point(c, p);
      REQUIRE(cp.t >= 0.0);
      REQUIRE(cp.t <= c.t_max());
      REQUIRE((cp.point - evaluate(c, cp.t)).norm() < 1e-12);
      REQUIRE(std::abs(cp.distance - (cp.point - p).norm()) < 1e-12);
      REQUIRE(cp.distance <= dense_distance(c, p, 10000) + 1e-9);
    }
  }
}

TEST_CASE("closest_point of a point on the curve is itself", "[geometry][closest_point]") {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 30; ++trial) {
    const Curve c = test::random_curve(rng, 3);
    const double t = std::uniform_real_distribution<double>(0.0, 3.0)(rng);
    const Vec3 p = evaluate(c, t);
    REQUIRE(closest_point(c, p).distance < 1e-9);
  }
}

TEST_CASE("closest_point handles degenerate curves and rejects bad input",
          "[geometry][closest_point]") {
  Curve point_curve;
  point_curve.control_points.assign(4, Vec3(1.0, 2.0, 3.0));
  point_curve.sharp = {false, false};
  const ClosestPoint cp = closest_point(point_curve, Vec3::Zero());
  REQUIRE(std::isfinite(cp.distance));
  REQUIRE(cp.distance == Approx(std::sqrt(14.0)));

  const Curve line = make_line(Vec3::Zero(), Vec3(3.0, 0.0, 0.0));
  const ClosestPoint on = closest_point(line, Vec3(1.0, 1.0, 0.0));
  REQUIRE(on.distance == Approx(1.0).margin(1e-12));
  REQUIRE(on.t == Approx(1.0 / 3.0).margin(1e-12));

  REQUIRE_THROWS_AS(closest_point(Curve{}, Vec3::Zero()), std::invalid_argument);
  REQUIRE_THROWS_AS(closest_point(line, Vec3(std::nan(""), 0.0, 0.0)), std::invalid_argument);
}

TEST_CASE("closest_point_on_polyline projects onto edges", "[geometry][closest_point]") {
  const std::vector<Vec3> poly{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  const ClosestPoint a = closest_point_on_polyline(poly, Vec3(0.25, 0.5, 0.0));
  REQUIRE(a.t == Approx(0.25));
  REQUIRE(a.distance == Approx(0.5));
  const ClosestPoint b = closest_point_on_polyline(poly, Vec3(2.0, 0.75, 0.0));
  REQUIRE(b.t == Approx(1.75));
  REQUIRE(b.distance == Approx(1.0));
  const ClosestPoint single = closest_point_on_polyline({Vec3(1, 1, 1)}, Vec3::Zero());
  REQUIRE(single.t == 0.0);
  REQUIRE(single.distance == Approx(std::sqrt(3.0)));
  REQUIRE_THROWS_AS(closest_point_on_polyline({}, Vec3::Zero()), std::invalid_argument);
}

TEST_CASE("closest_point_to_polyline finds the curve/polyline gap",
          "[geometry][closest_point]") {
  std::mt19937_64 rng(99);
  for (int trial = 0; trial < 20; ++trial) {
    const Curve c = test::random_curve(rng, 2);
    const std::vector<Vec3> poly{test::random_point(rng, 1.5), test::random_point(rng, 1.5),
                                 test::random_point(rng, 1.5)};
    const ClosestPoint r = closest_point_to_polyline(c, poly);
    REQUIRE((r.point - evaluate(c, r.t)).norm() < 1e-12);
    // Dense reference: curve samples against the exact polyline distance.
    double dense = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 4000; ++i) {
      const double t = c.t_max() * i / 4000.0;
      dense = std::min(dense, closest_point_on_polyline(poly, evaluate(c, t)).distance);
    }
    REQUIRE(r.distance <= dense + 1e-9);
  }
}
