#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "kernel/core/perspective_view.hpp"
#include "sketchlab/view.hpp"

using namespace sketchlab;

using test::distance_to_ray;
using test::make_view;

TEST_CASE("world_to_pixel then pixel_to_ray passes through the point", "[view]") {
  std::mt19937_64 rng(1234);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec3 eye(3 * u(rng), 1 + u(rng), 4 + u(rng));
    const Vec3 target(0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng));
    const View v = make_view(eye, target);
    const Vec3 world = target + 0.5 * Vec3(u(rng), u(rng), u(rng));
    const Vec3 px = world_to_pixel(v, world);
    REQUIRE(px.z() > 0.0);
    REQUIRE(px.z() < 1.0);
    const Ray ray = pixel_to_ray(v, px.head<2>());
    CHECK(ray.direction.norm() == Approx(1.0).epsilon(1e-12));
    CHECK(distance_to_ray(ray, world) < 1e-9);
    // The ray points away from the eye towards the point.
    CHECK(ray.direction.dot(world - eye) > 0.0);
    // The ray starts on the near plane: 0.1 from the eye along the view axis.
    const Vec3 axis = (target - eye).normalized();
    CHECK((ray.origin - eye).dot(axis) == Approx(0.1).epsilon(1e-9));
  }
}

TEST_CASE("pixel origin is bottom-left and the look-at target is the viewport centre", "[view]") {
  const View v = make_view(Vec3(0, 0, 5), Vec3::Zero());
  const Vec3 centre = world_to_pixel(v, Vec3::Zero());
  CHECK(centre.x() == Approx(10 + 600));
  CHECK(centre.y() == Approx(20 + 400));
  // +y in the world (up) maps to larger pixel y (origin bottom-left).
  CHECK(world_to_pixel(v, Vec3(0, 1, 0)).y() > centre.y());
  CHECK(world_to_pixel(v, Vec3(1, 0, 0)).x() > centre.x());
  // Nearer points have smaller depth.
  CHECK(world_to_pixel(v, Vec3(0, 0, 2)).z() < world_to_pixel(v, Vec3(0, 0, -2)).z());
}

TEST_CASE("points behind the camera get a negative depth and finite pixels", "[view]") {
  const View v = make_view(Vec3(0, 0, 5), Vec3::Zero());
  const Vec3 behind = world_to_pixel(v, Vec3(0.3, 0.2, 7));
  CHECK(behind.z() < 0.0);
  CHECK(behind.allFinite());
  const Vec3 on_eye_plane = world_to_pixel(v, Vec3(1, 0, 5));
  CHECK(on_eye_plane.z() < 0.0);
  CHECK(on_eye_plane.allFinite());
}

TEST_CASE("eye_position inverts look_at", "[view]") {
  const Vec3 eye(1.5, -2.0, 3.25);
  View v;
  v.view = look_at(eye, Vec3(0.1, 0.2, 0.3), Vec3::UnitY());
  CHECK((eye_position(v) - eye).norm() < 1e-12);
  // The view matrix is a rigid motion mapping the eye to the origin.
  const Mat3 r = v.view.block<3, 3>(0, 0);
  CHECK((r * r.transpose() - Mat3::Identity()).norm() < 1e-12);
  CHECK((v.view * eye.homogeneous()).head<3>().norm() < 1e-12);
  // The target lies on the -z axis in eye space.
  const Vec4 t = v.view * Vec3(0.1, 0.2, 0.3).homogeneous();
  CHECK(std::abs(t.x()) < 1e-12);
  CHECK(std::abs(t.y()) < 1e-12);
  CHECK(t.z() < 0.0);
}

TEST_CASE("perspective maps the near and far planes to clip depth -1 and 1", "[view]") {
  const Mat4 p = perspective(1.0, 2.0, 0.5, 20.0);
  const Vec4 n = p * Vec4(0, 0, -0.5, 1);
  const Vec4 f = p * Vec4(0, 0, -20, 1);
  CHECK(n.z() / n.w() == Approx(-1.0));
  CHECK(f.z() / f.w() == Approx(1.0));
  // A point at the top edge of the field of view maps to ndc y = 1.
  const Vec4 top = p * Vec4(0, std::tan(0.5) * 3.0, -3.0, 1);
  CHECK(top.y() / top.w() == Approx(1.0));
}

TEST_CASE("view functions reject degenerate input", "[view]") {
  CHECK_THROWS_AS(perspective(0.0, 1.0, 0.1, 10), std::invalid_argument);
  CHECK_THROWS_AS(perspective(1.0, -1.0, 0.1, 10), std::invalid_argument);
  CHECK_THROWS_AS(perspective(1.0, 1.0, 1.0, 0.5), std::invalid_argument);
  CHECK_THROWS_AS(look_at(Vec3::Zero(), Vec3::Zero(), Vec3::UnitY()), std::invalid_argument);
  CHECK_THROWS_AS(look_at(Vec3::Zero(), Vec3::UnitY(), Vec3::UnitY()), std::invalid_argument);
  View v = make_view(Vec3(0, 0, 5), Vec3::Zero());
  v.viewport = Vec4(0, 0, 0, 100);
  CHECK_THROWS_AS(world_to_pixel(v, Vec3::Zero()), std::invalid_argument);
  CHECK_THROWS_AS(pixel_to_ray(v, Vec2(1, 1)), std::invalid_argument);
  View singular;
  singular.projection = Mat4::Zero();
  CHECK_THROWS_AS(pixel_to_ray(singular, Vec2(0.5, 0.5)), std::invalid_argument);
}
