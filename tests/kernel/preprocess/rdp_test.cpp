#include <catch2/catch.hpp>

#include <random>

#include "kernel/preprocess/synthetic_strokes.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/preprocess/rdp.hpp"

using namespace sketchlab;

TEST_CASE("rdp keeps the endpoints and respects epsilon", "[preprocess][rdp]") {
  std::mt19937_64 rng(17);
  for (double eps : {0.0005, 0.002, 0.01}) {
    const auto s = test::sample_path(test::s_curve(0.4, 0.05), 300, 0.001, 0.5, rng);
    const auto idx = rdp_indices(s.points, eps);
    REQUIRE(idx.front() == 0);
    REQUIRE(idx.back() == s.points.size() - 1);
    for (std::size_t k = 1; k < idx.size(); ++k) REQUIRE(idx[k] > idx[k - 1]);
    // Every dropped point is within epsilon of the segment spanning it.
    for (std::size_t k = 0; k + 1 < idx.size(); ++k) {
      const std::vector<Vec3> seg{s.points[idx[k]], s.points[idx[k + 1]]};
      for (std::size_t i = idx[k] + 1; i < idx[k + 1]; ++i) {
        REQUIRE(closest_point_on_polyline(seg, s.points[i]).distance <= eps);
      }
    }
    const auto simplified = rdp_simplify(s.points, eps);
    REQUIRE(simplified.size() == idx.size());
    REQUIRE(simplified.size() < s.points.size());
  }
}

TEST_CASE("rdp keeps points farther than epsilon", "[preprocess][rdp]") {
  const std::vector<Vec3> p{{0, 0, 0}, {1, 0.5, 0}, {2, 0, 0}, {3, 0.001, 0}, {4, 0, 0}};
  REQUIRE(rdp_indices(p, 0.01) == std::vector<std::size_t>{0, 1, 2, 4});
  REQUIRE(rdp_indices(p, 0.0) == std::vector<std::size_t>{0, 1, 2, 3, 4});
  REQUIRE(rdp_indices(p, 10.0) == std::vector<std::size_t>{0, 4});
  REQUIRE(rdp_indices({}, 0.1).empty());
  REQUIRE(rdp_indices({Vec3::Zero()}, 0.1) == std::vector<std::size_t>{0});
  REQUIRE_THROWS_AS(rdp_indices(p, -1.0), std::invalid_argument);
}
