// Camera: a View with its matrices inverted once, agreeing with view.hpp.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

#include "kernel/core/perspective_view.hpp"
#include "sketchlab/camera.hpp"

using namespace sketchlab;

using test::distance_to_ray;
using test::make_view;
constexpr double fovy = test::test_fovy;

TEST_CASE("Camera projects and casts rays as view.hpp does", "[camera]") {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    const Vec3 eye(3 * u(rng), 1 + u(rng), 4 + u(rng));
    const View v = make_view(eye, Vec3(0.2 * u(rng), 0.2 * u(rng), 0.0));
    const Camera cam(v);
    const Vec3 p(0.5 * u(rng), 0.5 * u(rng), 0.5 * u(rng));
    const auto px = cam.project(p);
    REQUIRE(px);
    CHECK((*px - world_to_pixel(v, p).head<2>()).norm() < 1e-9);
    const Ray r = cam.ray(*px);
    CHECK(distance_to_ray(r, p) < 1e-9);
    CHECK(std::abs(r.direction.norm() - 1.0) < 1e-12);
    const Ray expected = pixel_to_ray(v, *px);
    CHECK((r.origin - expected.origin).norm() < 1e-9);
    CHECK((r.direction - expected.direction).norm() < 1e-9);
    // Depth in front of the eye along the viewing direction.
    CHECK(cam.eye_depth(p) == Approx((p - eye).dot(cam.forward())).margin(1e-9));
  }
}

TEST_CASE("Camera axes, film plane, pixel size and vanishing points", "[camera]") {
  const Vec3 eye(0, 0, 5);
  const View v = make_view(eye, Vec3::Zero());
  const Camera cam(v);
  CHECK((cam.forward() - Vec3(0, 0, -1)).norm() < 1e-12);
  CHECK((cam.right() - Vec3(1, 0, 0)).norm() < 1e-12);
  CHECK((cam.up() - Vec3(0, 1, 0)).norm() < 1e-12);
  const Plane film = cam.film_plane(Vec3(0.3, 0.1, -1));
  CHECK(film.point == Vec3(0.3, 0.1, -1));
  CHECK(film.normal == cam.forward());
  // At depth z a pixel is 2 z tan(fovy / 2) / height metres.
  for (double z : {1.0, 5.0, 20.0})
    CHECK(cam.world_per_pixel(Vec3(0, 0, 5 - z)) == Approx(2 * z * std::tan(fovy / 2) / 800).epsilon(1e-9));
  CHECK(cam.world_per_pixel(Vec3(0, 0, 6)) == 1.0);  // behind the eye
  // The vanishing point of a direction is where every line along it goes:
  // the pixel of the eye's own line, and the limit of far points.
  const Vec3 d = Vec3(1, 0.5, -2).normalized();
  const auto vp = cam.vanishing_point(d);
  REQUIRE(vp);
  CHECK((*vp - *cam.project(eye + d)).norm() < 1e-9);
  const auto far = cam.project(Vec3(0.1, 0.2, 0) + 1e6 * d);
  REQUIRE(far);
  CHECK((*vp - *far).norm() < 1e-2);
  CHECK_FALSE(cam.vanishing_point(Vec3(1, 0, 0)));  // parallel to the image plane
  // The centre of the viewport looks straight ahead.
  CHECK((*cam.project(Vec3(0, 0, -3)) - Vec2(10 + 600, 20 + 400)).norm() < 1e-9);
  CHECK(cam.dpi() == 96.0);
}

TEST_CASE("Camera refuses points behind the eye and broken views", "[camera]") {
  const Camera cam(make_view(Vec3(0, 0, 5), Vec3::Zero()));
  CHECK_FALSE(cam.project(Vec3(0, 0, 6)));
  CHECK_FALSE(cam.project(Vec3(0, 0, 5)));  // on the eye plane
  CHECK_FALSE(cam.project(Vec3(std::numeric_limits<double>::infinity(), 0, 0)));

  View singular = make_view(Vec3(0, 0, 5), Vec3::Zero());
  singular.projection.setZero();
  CHECK_THROWS_WITH(Camera(singular), "Camera: its camera (projection * view) is not invertible");
  View empty = make_view(Vec3(0, 0, 5), Vec3::Zero());
  empty.viewport = Vec4(0, 0, 0, 10);
  CHECK_THROWS_WITH(Camera(empty), "Camera: its viewport width and height must be finite and > 0");
}
