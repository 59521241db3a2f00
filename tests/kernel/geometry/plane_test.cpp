// Plane: the (n, d) conversion and ray intersection.
#include <catch2/catch.hpp>
#include <cmath>

#include "sketchlab/geometry/plane.hpp"

using namespace sketchlab;

TEST_CASE("plane_from_coefficients gives the plane n·x = d", "[plane]") {
  const Vec3 n = Vec3(1, 2, 2).normalized();
  const Plane p = plane_from_coefficients(Vec4(n.x(), n.y(), n.z(), 1.5));
  CHECK((p.normal - n).norm() < 1e-15);
  CHECK(p.normal.dot(p.point) == Approx(1.5).epsilon(1e-15));
  CHECK((p.point - 1.5 * n).norm() < 1e-15);
}

TEST_CASE("intersect meets the plane at any ray parameter", "[plane]") {
  const Plane floor{Vec3(0, -1, 0), Vec3::UnitY()};
  const auto ahead = intersect(Ray{Vec3(0, 1, 0), Vec3(0, -1, 1).normalized()}, floor);
  REQUIRE(ahead);
  CHECK((*ahead - Vec3(0, -1, 2)).norm() < 1e-12);
  // Behind the origin too.
  const auto behind = intersect(Ray{Vec3(0, 1, 0), Vec3(0, 1, 1).normalized()}, floor);
  REQUIRE(behind);
  CHECK((*behind - Vec3(0, -1, -2)).norm() < 1e-12);
  CHECK_FALSE(intersect(Ray{Vec3(0, 1, 0), Vec3::UnitX()}, floor));
}
