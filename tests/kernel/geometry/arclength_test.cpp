#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "kernel/geometry/random_curves.hpp"
#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/polyline.hpp"

using namespace sketchlab;

namespace {

double dense_length(const Curve& c, double t0, double t1, int per_unit) {
  std::vector<Vec3> pts;
  for (double t : test::dense_parameters(t0, t1, per_unit)) pts.push_back(evaluate(c, t));
  return polyline_length(pts);
}

}  // namespace

TEST_CASE("arclength matches a dense polyline", "[geometry][arclength]") {
  std::mt19937_64 rng(2718);
  for (int trial = 0; trial < 30; ++trial) {
    const int k = 1 + trial % 3;
    const Curve c = test::random_curve(rng, k);
    const double len = arclength(c);
    const double dense = dense_length(c, 0.0, c.t_max(), 200000);
    // The inscribed polyline is shorter by O(h^2); with h = 5e-6 it agrees
    // to ~1e-9 relative except near cusps, hence the 1e-7 margin.
    REQUIRE(len >= dense - 1e-12);
    REQUIRE(len == Approx(dense).epsilon(1e-7));
    REQUIRE(arclength(c, 0.0, c.t_max()) == Approx(len).epsilon(1e-12));
    std::uniform_real_distribution<double> u(0.0, c.t_max());
    double t0 = u(rng), t1 = u(rng);
    if (t1 < t0) std::swap(t0, t1);
    REQUIRE(arclength(c, t0, t1) == Approx(dense_length(c, t0, t1, 200000)).epsilon(1e-7));
  }
  const Curve line = make_line(Vec3::Zero(), Vec3(3, 4, 0));
  REQUIRE(arclength(line) == Approx(5.0).epsilon(1e-14));
}

TEST_CASE("parameter_at_arclength inverts arclength", "[geometry][arclength]") {
  std::mt19937_64 rng(1618);
  for (int trial = 0; trial < 20; ++trial) {
    const Curve c = test::random_curve(rng, 3);
    const double len = arclength(c);
    for (int i = 0; i <= 10; ++i) {
      const double s = len * i / 10.0;
      const double t = parameter_at_arclength(c, s);
      REQUIRE(arclength(c, 0.0, t) == Approx(s).margin(1e-9 * len));
    }
    REQUIRE(parameter_at_arclength(c, -1.0) == 0.0);
    REQUIRE(parameter_at_arclength(c, 2.0 * len) == c.t_max());
  }
}

TEST_CASE("sampling by arclength is uniform", "[geometry][arclength]") {
  std::mt19937_64 rng(11);
  const Curve c = test::random_curve(rng, 2);
  const auto ts = arclength_parameters(c, 21);
  REQUIRE(ts.size() == 21);
  REQUIRE(ts.front() == 0.0);
  REQUIRE(ts.back() == c.t_max());
  const double len = arclength(c);
  for (std::size_t i = 1; i < ts.size(); ++i) {
    REQUIRE(ts[i] >= ts[i - 1]);
    REQUIRE(arclength(c, ts[i - 1], ts[i]) == Approx(len / 20.0).margin(1e-9 * len));
  }
  const auto pts = sample_by_arclength(c, 21);
  REQUIRE((pts.front() - c.control_points.front()).norm() == 0.0);
  REQUIRE((pts.back() - c.control_points.back()).norm() == 0.0);

  const double spacing = 0.05;
  const auto spaced = sample_with_spacing(c, spacing);
  REQUIRE(spaced.size() >= 2);
  for (std::size_t i = 1; i < spaced.size(); ++i) {
    REQUIRE((spaced[i] - spaced[i - 1]).norm() <= spacing + 1e-12);
  }
  REQUIRE(polyline_length(spaced) <= len + 1e-12);

  REQUIRE_THROWS_AS(arclength_parameters(c, 1), std::invalid_argument);
  REQUIRE_THROWS_AS(sample_with_spacing(c, 0.0), std::invalid_argument);
  REQUIRE_THROWS_AS(sample_with_spacing(c, std::nan("")), std::invalid_argument);
  REQUIRE_THROWS_AS(arclength(c, 1.0, 0.5), std::invalid_argument);
}

TEST_CASE("sampling with a spacing and a cap on the points", "[geometry][arclength]") {
  const Curve metre = make_line(Vec3(0, 0, 0), Vec3(1, 0, 0));
  // Within the cap: the same points as without one.
  CHECK(sample_with_spacing(metre, 0.01, 1000) == sample_with_spacing(metre, 0.01));
  CHECK(sample_with_spacing(metre, 0.01, 101).size() == 101);
  // Beyond it: evenly spread over the whole curve, ends kept.
  const auto capped = sample_with_spacing(metre, 0.01, 11);
  REQUIRE(capped.size() == 11);
  CHECK(capped.front() == Vec3(0, 0, 0));
  CHECK(capped.back() == Vec3(1, 0, 0));
  for (std::size_t i = 1; i < capped.size(); ++i) CHECK((capped[i] - capped[i - 1]).norm() == Approx(0.1));
  // A curve kilometres long (one glitch sample) no longer throws.
  const Curve glitch = make_line(Vec3(0, 0, 0), Vec3(2e6, 0, 0));
  CHECK_THROWS_AS(sample_with_spacing(glitch, 0.005), std::invalid_argument);
  CHECK(sample_with_spacing(glitch, 0.005, 10001).size() == 10001);
  CHECK_THROWS_WITH(sample_with_spacing(metre, 0.01, 1), Catch::Contains("max_points must be >= 2"));
  CHECK_THROWS_AS(sample_with_spacing(metre, 0.0, 10), std::invalid_argument);
}

TEST_CASE("arclength sampling of a zero-length curve stays finite", "[geometry][arclength]") {
  const Curve dot = make_line(Vec3(1, 1, 1), Vec3(1, 1, 1));
  REQUIRE(arclength(dot) == 0.0);
  const auto pts = sample_with_spacing(dot, 0.01);
  REQUIRE(pts.size() == 2);
  for (const Vec3& p : pts) REQUIRE(p.allFinite());
}

TEST_CASE("an arclength that overflows comes back non-finite without refining", "[geometry][arclength]") {
  // Before the guard the quadrature never agreed with itself and recursed to
  // depth 40 on each half (a 1e300 control point in a CASSIE graph hung
  // soapfilm_compare).
  Curve c;
  c.control_points = {Vec3(0, 0, 0), Vec3(1e300, 0, 0), Vec3(1e300, 1e300, 0), Vec3(0, 1e300, 1e300)};
  c.sharp = {false, false};
  REQUIRE_FALSE(std::isfinite(arclength(c)));
}
