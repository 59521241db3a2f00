#include <catch2/catch.hpp>

#include <numbers>
#include <random>

#include "kernel/preprocess/synthetic_strokes.hpp"
#include "sketchlab/preprocess/line_detection.hpp"

using namespace sketchlab;

TEST_CASE("straight noisy strokes drawn quickly are lines", "[preprocess][line_detection]") {
  std::mt19937_64 rng(1);
  const LineDetectionParams params;
  for (int trial = 0; trial < 10; ++trial) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const Vec3 a(u(rng), u(rng), u(rng));
    const Vec3 b = a + Vec3(0.3, 0.1 * trial, -0.05);
    const auto s = test::sample_path(test::straight(a, b), 200, 0.001, 0.5, rng);
    const LineDetection r = detect_line(s.points, s.times, params);
    REQUIRE(r.is_line);
    REQUIRE(r.length_ratio >= params.min_length_ratio);
    REQUIRE(fit_pca_line(s.points).max_deviation < 0.01);
  }
}

TEST_CASE("arcs and S-curves are not lines", "[preprocess][line_detection]") {
  std::mt19937_64 rng(2);
  const LineDetectionParams params;
  const auto arc = test::sample_path(test::arc(0.2, std::numbers::pi / 2), 200, 0.001, 0.5, rng);
  REQUIRE_FALSE(detect_line(arc.points, arc.times, params).is_line);
  REQUIRE_FALSE(fit_pca_line(arc.points).is_line);
  const auto s = test::sample_path(test::s_curve(0.4, 0.04), 300, 0.001, 0.5, rng);
  REQUIRE_FALSE(detect_line(s.points, s.times, params).is_line);
  REQUIRE_FALSE(fit_pca_line(s.points).is_line);
}

TEST_CASE("slow straight strokes stay curves", "[preprocess][line_detection]") {
  std::mt19937_64 rng(3);
  const LineDetectionParams params;
  const auto slow =
      test::sample_path(test::straight(Vec3::Zero(), Vec3(0.3, 0, 0)), 200, 0.001, 0.05, rng);
  const LineDetection r = detect_line(slow.points, slow.times, params);
  REQUIRE(r.length_ratio >= params.min_length_ratio);
  REQUIRE(r.mean_speed < params.min_speed);
  REQUIRE_FALSE(r.is_line);
  // Without timing the speed test is skipped.
  REQUIRE(detect_line(slow.points, {}, params).is_line);
}

TEST_CASE("detect_line rejects bad input", "[preprocess][line_detection]") {
  const LineDetectionParams params;
  const std::vector<Vec3> p{Vec3::Zero(), Vec3::UnitX()};
  REQUIRE_THROWS_AS(detect_line({Vec3::Zero()}, {}, params), std::invalid_argument);
  REQUIRE_THROWS_AS(detect_line({Vec3::Zero(), Vec3::Zero()}, {}, params), std::invalid_argument);
  REQUIRE_THROWS_AS(detect_line(p, {0.0}, params), std::invalid_argument);
  REQUIRE_THROWS_AS(detect_line(p, {1.0, 0.5}, params), std::invalid_argument);
  LineDetectionParams bad;
  bad.resample_spacing = 0.0;
  REQUIRE_THROWS_AS(detect_line(p, {}, bad), std::invalid_argument);
}
