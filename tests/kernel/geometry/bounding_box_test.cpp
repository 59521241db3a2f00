#include <catch2/catch.hpp>

#include <limits>
#include <random>

#include "kernel/geometry/random_curves.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/bounding_box.hpp"

using namespace sketchlab;

namespace {

Box3 dense_box(const Curve& c, double t0, double t1, int per_unit) {
  Box3 b;
  b.setEmpty();
  for (double t : test::dense_parameters(t0, t1, per_unit)) b.extend(evaluate(c, t));
  return b;
}

// Dense samples are contained, and each face is touched by them: the box is
// tight up to the sampling error, which is quadratic in the spacing at an
// interior extremum (|B''| <= 12 for coordinates in [-1,1], spacing 1e-5).
void require_tight(const Box3& box, const Box3& dense) {
  for (int i = 0; i < 3; ++i) {
    REQUIRE(box.min()[i] <= dense.min()[i] + 1e-15);
    REQUIRE(box.max()[i] >= dense.max()[i] - 1e-15);
    REQUIRE(dense.min()[i] - box.min()[i] <= 1e-9);
    REQUIRE(box.max()[i] - dense.max()[i] <= 1e-9);
  }
}

}  // namespace

TEST_CASE("bounding_box is tight on random curves", "[geometry][bounding_box]") {
  std::mt19937_64 rng(123);
  for (int trial = 0; trial < 40; ++trial) {
    const int k = 1 + trial % 3;
    const Curve c = test::random_curve(rng, k);
    require_tight(bounding_box(c), dense_box(c, 0.0, c.t_max(), 100000));
  }
}

TEST_CASE("bounding_box of a parameter range is tight", "[geometry][bounding_box]") {
  std::mt19937_64 rng(321);
  for (int trial = 0; trial < 20; ++trial) {
    const Curve c = test::random_curve(rng, 3);
    std::uniform_real_distribution<double> u(0.0, 3.0);
    double t0 = u(rng), t1 = u(rng);
    if (t1 < t0) std::swap(t0, t1);
    require_tight(bounding_box(c, t0, t1), dense_box(c, t0, t1, 100000));
  }
}

TEST_CASE("bounding_box of a line is its endpoints' box", "[geometry][bounding_box]") {
  const Curve line = make_line(Vec3(1, -2, 3), Vec3(-1, 2, 5));
  const Box3 b = bounding_box(line);
  REQUIRE(b.min() == Vec3(-1, -2, 3));
  REQUIRE(b.max() == Vec3(1, 2, 5));
  REQUIRE_THROWS_AS(bounding_box(line, 0.7, 0.2), std::invalid_argument);
  REQUIRE_THROWS_AS(bounding_box(Curve{}), std::invalid_argument);
}
