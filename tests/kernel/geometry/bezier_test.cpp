#include <catch2/catch.hpp>

#include <random>

#include "kernel/geometry/random_curves.hpp"
#include "sketchlab/geometry/bezier.hpp"

using namespace sketchlab;

TEST_CASE("locate maps global parameters to segments", "[geometry][bezier]") {
  std::mt19937_64 rng(1);
  const Curve c = test::random_curve(rng, 3);
  REQUIRE(locate(c, 0.0) == std::pair<int, double>{0, 0.0});
  REQUIRE(locate(c, 1.0) == std::pair<int, double>{1, 0.0});
  REQUIRE(locate(c, 3.0) == std::pair<int, double>{2, 1.0});
  REQUIRE(locate(c, -2.0) == std::pair<int, double>{0, 0.0});
  REQUIRE(locate(c, 9.0) == std::pair<int, double>{2, 1.0});
  REQUIRE_THROWS_AS(locate(c, std::nan("")), std::invalid_argument);
  REQUIRE_THROWS_AS(locate(Curve{}, 0.0), std::invalid_argument);
  REQUIRE_THROWS_AS(segment_points(c, 3), std::out_of_range);
}

TEST_CASE("evaluation interpolates joints and derivatives match finite differences",
          "[geometry][bezier]") {
  std::mt19937_64 rng(2);
  const Curve c = test::random_curve(rng, 3);
  for (int k = 0; k <= 3; ++k) {
    REQUIRE((evaluate(c, k) - c.control_points[3 * k]).norm() < 1e-15);
  }
  // End derivatives are 3 (P1 - P0) and 3 (P3 - P2).
  REQUIRE((derivative(c, 0.0) - 3.0 * (c.control_points[1] - c.control_points[0])).norm() < 1e-14);
  REQUIRE((derivative(c, 3.0) - 3.0 * (c.control_points[9] - c.control_points[8])).norm() < 1e-14);
  const double h = 1e-6;
  for (double t : {0.3, 1.5, 2.7}) {
    const Vec3 fd = (evaluate(c, t + h) - evaluate(c, t - h)) / (2 * h);
    REQUIRE((derivative(c, t) - fd).norm() < 1e-7);
    const Vec3 fd2 = (derivative(c, t + h) - derivative(c, t - h)) / (2 * h);
    REQUIRE((second_derivative(c, t) - fd2).norm() < 1e-6);
    REQUIRE(tangent(c, t).norm() == Approx(1.0));
  }
}

TEST_CASE("tangent falls back where the derivative vanishes", "[geometry][bezier]") {
  Curve c;
  c.control_points = {Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(2, 0, 0)};
  c.sharp = {false, false};
  REQUIRE(derivative(c, 0.0).norm() == 0.0);
  REQUIRE((tangent(c, 0.0) - Vec3(1, 1, 0).normalized()).norm() < 1e-15);
  const Curve dot = make_line(Vec3::Ones(), Vec3::Ones());
  const Vec3 t = tangent(dot, 0.5);
  REQUIRE(t.allFinite());
  REQUIRE(t.norm() == Approx(1.0));
}
