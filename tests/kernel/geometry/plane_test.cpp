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

TEST_CASE("plane_residual is the largest distance to the centroid's plane of that normal", "[plane]") {
  // Centroid z = 0.25: the farthest point (z = 1) is 0.75 off the plane z = 0.25.
  const std::vector<Vec3> pts{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 7, 1}};
  CHECK(std::abs(plane_residual(pts, Vec3::UnitZ()) - 0.75) < 1e-15);
  CHECK(std::abs(plane_residual(pts, -Vec3::UnitZ()) - 0.75) < 1e-15);  // orientation does not matter
  CHECK(plane_residual({{1, 2, 3}, {4, 5, 3}}, Vec3::UnitZ()) == 0.0);
  CHECK(plane_residual({}, Vec3::UnitZ()) == 0.0);
}
