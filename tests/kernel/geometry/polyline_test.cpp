#include <catch2/catch.hpp>

#include "sketchlab/geometry/polyline.hpp"

using namespace sketchlab;

TEST_CASE("polyline lengths and resampling", "[geometry][polyline]") {
  const std::vector<Vec3> p{{0, 0, 0}, {3, 0, 0}, {3, 4, 0}};
  REQUIRE(polyline_length(p) == 7.0);
  REQUIRE(cumulative_length(p) == std::vector<double>{0.0, 3.0, 7.0});
  REQUIRE((point_at_length(p, 5.0) - Vec3(3, 2, 0)).norm() < 1e-15);
  REQUIRE(point_at_length(p, -1.0) == p.front());
  REQUIRE(point_at_length(p, 100.0) == p.back());
  const auto r = resample_polyline(p, 8);
  REQUIRE(r.size() == 8);
  REQUIRE(r.front() == p.front());
  REQUIRE(r.back() == p.back());
  for (std::size_t i = 1; i < r.size(); ++i) {
    // Equal spacing along the polyline: each step covers 1 unit of length.
    REQUIRE(cumulative_length(r)[i] == Approx(static_cast<double>(i)).margin(1e-12));
  }
  REQUIRE(polyline_length({}) == 0.0);
  REQUIRE(polyline_length({Vec3::Ones()}) == 0.0);
  REQUIRE_THROWS_AS(resample_polyline(p, 1), std::invalid_argument);
  REQUIRE_THROWS_AS(resample_polyline({}, 4), std::invalid_argument);
  const auto same = resample_polyline({Vec3::Ones(), Vec3::Ones()}, 3);
  for (const Vec3& x : same) REQUIRE(x == Vec3::Ones());
}
