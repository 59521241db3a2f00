// Item 14's planarity test (plane_fit.cpp): the 2δ distance is measured to
// the least-squares plane, whose normal is snapped to an axis afterwards
// (CHI 2021 §4.2), or, as a variant, to the snapped plane.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "plane_fit.hpp"

using namespace sketchlab;
using namespace sketchlab::cassie;

namespace {

// Points on the plane through the origin whose normal is z tilted by `tilt`
// about x: (x, y cos t, y sin t).
std::vector<Vec3> tilted(double tilt) {
  std::vector<Vec3> p;
  for (double x : {-0.2, 0.0, 0.2})
    for (double y : {0.0, 0.1, 0.2}) p.emplace_back(x, y * std::cos(tilt), y * std::sin(tilt));
  return p;
}

}  // namespace

TEST_CASE("The planarity test measures the fitted plane, then snaps its normal", "[cassie]") {
  const double tilt = 25.0 * std::numbers::pi / 180;  // within θ = π/6 of z
  const double theta = std::numbers::pi / 6;
  const std::vector<Vec3> pts = tilted(tilt);
  // Off the snapped plane z = const by ±0.1·sin 25° = 4.2 cm, beyond 2δ = 4 cm.
  const double off_snapped = 0.1 * std::sin(tilt);

  const PlaneFit fitted = fit_plane(pts, 0.04, theta, false);
  CHECK(fitted.planar);
  CHECK(fitted.axis == 2);
  CHECK((fitted.normal - Vec3::UnitZ()).norm() < 1e-12);
  CHECK(fitted.max_distance < 1e-12);

  const PlaneFit snapped = fit_plane(pts, 0.04, theta, true);
  CHECK_FALSE(snapped.planar);
  CHECK(snapped.axis == 2);
  CHECK(std::abs(snapped.max_distance - off_snapped) < 1e-12);
  CHECK(fit_plane(pts, off_snapped + 1e-9, theta, true).planar);

  // Beyond θ the normal stays the fitted one and both tests agree.
  const PlaneFit free = fit_plane(tilted(40.0 * std::numbers::pi / 180), 0.04, theta, true);
  CHECK(free.planar);
  CHECK(free.axis == -1);
  CHECK(std::abs(std::abs(free.normal.dot(Vec3(0, -std::sin(0.698131700797732), std::cos(0.698131700797732)))) - 1) < 1e-12);

  // Collinear points have no plane.
  CHECK_FALSE(fit_plane({{0, 0, 0}, {0.1, 0, 0}, {0.2, 0, 0}}, 0.04, theta, false).planar);
}
