#include <catch2/catch.hpp>
#include <random>
#include <stdexcept>

#include "sketchlab/workspace.hpp"

using namespace sketchlab;

TEST_CASE("nearest_grid_point is a grid point no farther than any neighbour", "[workspace]") {
  Workspace ws;
  ws.grid_enabled = true;
  ws.grid_spacing = 0.25;
  ws.grid_origin = Vec3::Constant(0.125);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 200; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    const Vec3 g = nearest_grid_point(ws, p);
    const Vec3 k = (g - ws.grid_origin) / ws.grid_spacing;
    CHECK((k - k.array().round().matrix()).norm() < 1e-9);
    for (int axis = 0; axis < 3; ++axis) {
      for (double step : {-1.0, 1.0}) {
        const Vec3 other = g + step * ws.grid_spacing * Vec3::Unit(axis);
        CHECK((p - g).norm() <= (p - other).norm() + 1e-12);
      }
    }
  }
  CHECK((nearest_grid_point(ws, Vec3(0.13, 1.1, 0.4)) - Vec3(0.125, 1.125, 0.375)).norm() < 1e-15);
}

TEST_CASE("nearest_grid_point needs an enabled grid with positive spacing", "[workspace]") {
  Workspace ws;
  CHECK_THROWS_AS(nearest_grid_point(ws, Vec3::Zero()), std::invalid_argument);
  ws.grid_enabled = true;
  ws.grid_spacing = 0.0;
  CHECK_THROWS_AS(nearest_grid_point(ws, Vec3::Zero()), std::invalid_argument);
}

TEST_CASE("mirror_point reflects across the plane and is an involution", "[workspace]") {
  Workspace ws;
  ws.mirror_normal = Vec3(2.0, 0.0, 0.0);  // not unit on purpose
  ws.mirror_offset = 0.25;                 // plane 2x = 0.25, i.e. x = 0.125
  CHECK((mirror_point(ws, Vec3(0.2, 1, 2)) - Vec3(0.05, 1, 2)).norm() < 1e-15);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  ws.mirror_normal = Vec3(u(rng), u(rng), u(rng));
  ws.mirror_offset = u(rng);
  for (int i = 0; i < 100; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    const Vec3 m = mirror_point(ws, p);
    CHECK((mirror_point(ws, m) - p).norm() < 1e-12);
    // The midpoint lies on the plane and the segment is along the normal.
    const Vec3 n = ws.mirror_normal.normalized();
    CHECK(std::abs(n.dot((p + m) / 2) - ws.mirror_offset / ws.mirror_normal.norm()) < 1e-12);
    CHECK((p - m).cross(n).norm() < 1e-12);
  }
  ws.mirror_normal = Vec3::Zero();
  CHECK_THROWS_AS(mirror_point(ws, Vec3::Zero()), std::invalid_argument);
}
