#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include "kernel/preprocess/synthetic_strokes.hpp"
#include "sketchlab/preprocess/hooks.hpp"

using namespace sketchlab;

namespace {

// A straight 40 cm stroke along +x with hooks of the given lengths at both
// ends, each turning by `angle`, with 0.7 mm jitter; and the true corners.
struct Hooked {
  std::vector<Vec3> points;
  std::size_t start_corner = 0;
  std::size_t end_corner = 0;
};

Hooked hooked_stroke(double start_len, double end_len, double angle, std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 0.0007);
  auto jitter = [&]() { return Vec3(g(rng), g(rng), g(rng)); };
  const double step = 0.002;
  Hooked h;
  // Start hook: travels along `in` and turns by `angle` into +x at the origin.
  const Vec3 in(std::cos(angle), -std::sin(angle), 0.0);
  const int n_start = static_cast<int>(std::round(start_len / step));
  for (int i = n_start; i > 0; --i) h.points.push_back(-in * (i * step) + jitter());
  h.start_corner = h.points.size();
  const int n_body = 200;
  for (int i = 0; i <= n_body; ++i) h.points.push_back(Vec3(i * step, 0, 0) + jitter());
  h.end_corner = h.points.size() - 1;
  const Vec3 end = Vec3(n_body * step, 0, 0);
  const Vec3 out_dir(std::cos(angle), 0.0, std::sin(angle));  // turn by `angle`
  const int n_end = static_cast<int>(std::round(end_len / step));
  for (int i = 1; i <= n_end; ++i) h.points.push_back(end + out_dir * (i * step) + jitter());
  return h;
}

}  // namespace

TEST_CASE("hooks at both ends are removed", "[preprocess][hooks]") {
  std::mt19937_64 rng(8);
  const HookParams params;  // CASSIE defaults at zoom 1
  for (double angle : {std::numbers::pi / 3, std::numbers::pi / 2, 2.5}) {
    for (double len : {0.015, 0.03, 0.05}) {
      const Hooked h = hooked_stroke(len, 0.8 * len, angle, rng);
      const IndexRange r = find_hookless_range(h.points, params);
      // The cut lands at the true corner, within the jitter of a few samples.
      REQUIRE(std::abs(static_cast<double>(r.first) - static_cast<double>(h.start_corner)) <= 3.0);
      REQUIRE(std::abs(static_cast<double>(r.last) - static_cast<double>(h.end_corner)) <= 3.0);
    }
  }
}

TEST_CASE("a hook that bends is kept when hooks must be straight", "[preprocess][hooks]") {
  // 100 points along +x; before them a 30 mm circular arc turning by 80°
  // that arrives along +y and meets the body at a 90° turn: a hook for
  // CASSIE's rule, but the piece bends as much as the turn at the cut.
  std::vector<Vec3> p;
  const double radius = 0.03 / (80.0 * std::numbers::pi / 180.0);
  for (int i = 30; i > 0; --i) {
    const double th = 0.001 * i / radius;  // back along the arc from the origin
    p.push_back(Vec3(radius * (std::cos(th) - 1.0), -radius * std::sin(th), 0.0));
  }
  const std::size_t cut = p.size();
  for (int i = 0; i < 100; ++i) p.push_back(Vec3(0.004 * i, 0.0, 0.0));
  HookParams params;
  REQUIRE(std::abs(static_cast<double>(find_hookless_range(p, params).first) - static_cast<double>(cut)) <= 1.0);
  params.max_bend_ratio = 0.2;
  CHECK(find_hookless_range(p, params).first == 0);
  // A straight flick still qualifies: same cuts as without the test.
  std::mt19937_64 rng(11);
  for (double angle : {std::numbers::pi / 2, 2.5}) {
    const Hooked h = hooked_stroke(0.05, 0.04, angle, rng);
    const IndexRange r = find_hookless_range(h.points, params);
    CHECK(std::abs(static_cast<double>(r.first) - static_cast<double>(h.start_corner)) <= 3.0);
    CHECK(std::abs(static_cast<double>(r.last) - static_cast<double>(h.end_corner)) <= 3.0);
  }
}

TEST_CASE("hook-free strokes are left intact", "[preprocess][hooks]") {
  std::mt19937_64 rng(9);
  const HookParams params;
  const std::vector<test::SyntheticStroke> strokes{
      test::sample_path(test::straight(Vec3::Zero(), Vec3(0.4, 0.1, 0)), 200, 0.0007, 0.5, rng),
      test::sample_path(test::arc(0.15, std::numbers::pi), 250, 0.0007, 0.5, rng),
      test::sample_path(test::arc(0.1, 1.8 * std::numbers::pi), 300, 0.0007, 0.5, rng),
      test::sample_path(test::s_curve(0.4, 0.05), 300, 0.0007, 0.5, rng),
  };
  for (const auto& s : strokes) {
    const IndexRange r = find_hookless_range(s.points, params);
    REQUIRE(r.first == 0);
    REQUIRE(r.last == s.points.size() - 1);
  }
}

TEST_CASE("hooks longer than the limits are kept", "[preprocess][hooks]") {
  std::mt19937_64 rng(10);
  const HookParams params;  // at most 6 cm
  const Hooked h = hooked_stroke(0.1, 0.0, std::numbers::pi / 2, rng);
  const IndexRange r = find_hookless_range(h.points, params);
  REQUIRE(r.first == 0);
}

TEST_CASE("find_hookless_range rejects bad input", "[preprocess][hooks]") {
  const HookParams params;
  REQUIRE_THROWS_AS(find_hookless_range({Vec3::Zero()}, params), std::invalid_argument);
  REQUIRE_THROWS_AS(find_hookless_range({Vec3::Zero(), Vec3(NAN, 0, 0)}, params),
                    std::invalid_argument);
  HookParams bad;
  bad.max_fraction = 0.7;
  REQUIRE_THROWS_AS(find_hookless_range({Vec3::Zero(), Vec3::UnitX()}, bad),
                    std::invalid_argument);
  HookParams bad_bend;
  bad_bend.max_bend_ratio = -0.1;
  REQUIRE_THROWS_AS(find_hookless_range({Vec3::Zero(), Vec3::UnitX()}, bad_bend),
                    std::invalid_argument);
  bad_bend.max_bend_ratio = NAN;
  REQUIRE_THROWS_AS(find_hookless_range({Vec3::Zero(), Vec3::UnitX()}, bad_bend),
                    std::invalid_argument);
  const IndexRange two = find_hookless_range({Vec3::Zero(), Vec3::UnitX()}, params);
  REQUIRE(two == IndexRange{0, 1});
}
