#include <catch2/catch.hpp>

#include <random>

#include "kernel/geometry/random_curves.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/geometry/split.hpp"

using namespace sketchlab;

TEST_CASE("split halves trace the original curve", "[geometry][split]") {
  std::mt19937_64 rng(31337);
  for (int trial = 0; trial < 40; ++trial) {
    const int k = 1 + trial % 3;
    Curve c = test::random_curve(rng, k);
    c.sharp[0] = true;
    const double t = std::uniform_real_distribution<double>(0.01, k - 0.01)(rng);
    const auto [left, right] = split(c, t);
    REQUIRE(validate(left).empty());
    REQUIRE(validate(right).empty());
    REQUIRE(left.segment_count() + right.segment_count() == c.segment_count() + 1);
    // Joint continuity (position), and both ends preserved.
    REQUIRE((left.control_points.back() - right.control_points.front()).norm() == 0.0);
    REQUIRE((left.control_points.back() - evaluate(c, t)).norm() < 1e-12);
    REQUIRE((left.control_points.front() - c.control_points.front()).norm() == 0.0);
    REQUIRE((right.control_points.back() - c.control_points.back()).norm() == 0.0);
    // Tangent continuity across the cut: the derivative directions agree.
    REQUIRE((tangent(left, left.t_max()) - tangent(right, 0.0)).norm() < 1e-9);
    REQUIRE(left.sharp.front());
    REQUIRE_FALSE(left.sharp.back());
    REQUIRE_FALSE(right.sharp.front());
    // Every point of each half lies on the original within 1e-12.
    for (const Curve* half : {&left, &right}) {
      for (int i = 0; i <= 200; ++i) {
        const Vec3 p = evaluate(*half, half->t_max() * i / 200.0);
        REQUIRE(closest_point(c, p).distance < 1e-12);
      }
    }
  }
}

TEST_CASE("split rejects parameters outside the open range", "[geometry][split]") {
  const Curve line = make_line(Vec3::Zero(), Vec3::UnitX());
  REQUIRE_THROWS_AS(split(line, 0.0), std::invalid_argument);
  REQUIRE_THROWS_AS(split(line, 1.0), std::invalid_argument);
  REQUIRE_THROWS_AS(split(line, std::nan("")), std::invalid_argument);
  const auto [a, b] = split(line, 0.25);
  REQUIRE(a.kind == CurveKind::line);
  REQUIRE(b.kind == CurveKind::line);
  REQUIRE((evaluate(a, 1.0) - Vec3(0.25, 0, 0)).norm() < 1e-15);
}

TEST_CASE("insert_joint preserves the shape", "[geometry][split]") {
  std::mt19937_64 rng(4242);
  for (int trial = 0; trial < 30; ++trial) {
    const Curve c = test::random_curve(rng, 2);
    const double t = std::uniform_real_distribution<double>(0.0, 2.0)(rng);
    const auto [d, j] = insert_joint(c, t);
    REQUIRE(validate(d).empty());
    REQUIRE(d.segment_count() == 3);
    REQUIRE((d.control_points[3 * j] - evaluate(c, t)).norm() < 1e-12);
    REQUIRE_FALSE(d.sharp[j]);
    // Same point set: samples of either curve lie on the other.
    for (int i = 0; i <= 100; ++i) {
      REQUIRE(closest_point(c, evaluate(d, d.t_max() * i / 100.0)).distance < 1e-12);
      REQUIRE(closest_point(d, evaluate(c, c.t_max() * i / 100.0)).distance < 1e-12);
    }
  }
  // At an existing joint the curve is unchanged.
  const Curve c = test::random_curve(rng, 2);
  const auto [same, j] = insert_joint(c, 1.0);
  REQUIRE(same == c);
  REQUIRE(j == 1);
}

TEST_CASE("sub_curve extracts a parameter range", "[geometry][split]") {
  std::mt19937_64 rng(5);
  const Curve c = test::random_curve(rng, 3);
  const Curve s = sub_curve(c, 0.4, 2.3);
  REQUIRE(validate(s).empty());
  REQUIRE((s.control_points.front() - evaluate(c, 0.4)).norm() < 1e-12);
  REQUIRE((s.control_points.back() - evaluate(c, 2.3)).norm() < 1e-12);
  for (int i = 0; i <= 100; ++i) {
    REQUIRE(closest_point(c, evaluate(s, s.t_max() * i / 100.0)).distance < 1e-12);
  }
  REQUIRE(sub_curve(c, 0.0, 3.0) == c);
  REQUIRE_THROWS_AS(sub_curve(c, 1.0, 1.0), std::invalid_argument);
}
