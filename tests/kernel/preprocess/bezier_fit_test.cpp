#include <catch2/catch.hpp>

#include <numbers>
#include <random>

#include "kernel/preprocess/synthetic_strokes.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/preprocess/bezier_fit.hpp"

using namespace sketchlab;

namespace {

double max_distance(const Curve& c, const std::vector<Vec3>& pts) {
  double worst = 0.0;
  for (const Vec3& p : pts) worst = std::max(worst, closest_point(c, p).distance);
  return worst;
}

void require_g1_inside_sections(const Curve& c) {
  for (int k = 1; k < c.segment_count(); ++k) {
    if (c.sharp[k]) continue;
    const Vec3 in = c.control_points[3 * k] - c.control_points[3 * k - 1];
    const Vec3 out = c.control_points[3 * k + 1] - c.control_points[3 * k];
    REQUIRE(in.cross(out).norm() <= 1e-9 * in.norm() * out.norm());
    REQUIRE(in.dot(out) > 0.0);
  }
}

}  // namespace

TEST_CASE("fit stays within tolerance on noisy strokes", "[preprocess][bezier_fit]") {
  std::mt19937_64 rng(77);
  BezierFitParams params;  // tolerance 1 cm = 0.5δ
  const std::vector<std::function<Vec3(double)>> paths{
      test::arc(0.2, std::numbers::pi), test::s_curve(0.5, 0.08), test::arc(0.1, 5.0),
      [](double s) {  // helix
        return Vec3(0.1 * std::cos(8 * s), 0.1 * std::sin(8 * s), 0.3 * s);
      }};
  for (double tol : {0.002, 0.005, 0.01}) {
    params.tolerance = tol;
    for (const auto& path : paths) {
      const auto s = test::sample_path(path, 300, 0.001, 0.5, rng);
      const Curve c = fit_poly_bezier(s.points, params);
      REQUIRE(validate(c).empty());
      REQUIRE(c.kind == CurveKind::bezier);
      REQUIRE(c.control_points.front() == s.points.front());
      REQUIRE(c.control_points.back() == s.points.back());
      REQUIRE(max_distance(c, s.points) <= tol);
      require_g1_inside_sections(c);
      // With a tolerance well above the jitter (|noise| ~ 1.7 mm) the fit
      // smooths with far fewer segments than samples instead of interpolating.
      if (tol >= 0.005) REQUIRE(c.segment_count() < 30);
    }
  }
}

TEST_CASE("an L-shaped stroke keeps a sharp joint at the corner", "[preprocess][bezier_fit]") {
  std::mt19937_64 rng(78);
  const BezierFitParams params;
  const auto s = test::sample_path(test::l_shape(0.3), 301, 0.001, 0.5, rng);
  const auto corners = find_corners(s.points, params);
  REQUIRE(corners.size() == 1);
  REQUIRE((s.points[corners[0]] - Vec3(0.3, 0, 0)).norm() < 0.01);
  const Curve c = fit_poly_bezier(s.points, params);
  REQUIRE(max_distance(c, s.points) <= params.tolerance);
  int sharp_count = 0;
  for (int k = 0; k <= c.segment_count(); ++k) {
    if (!c.sharp[k]) continue;
    ++sharp_count;
    REQUIRE((c.control_points[3 * k] - Vec3(0.3, 0, 0)).norm() < 0.01);
    const Vec3 in = tangent(c, k - 1e-9), out = tangent(c, k);
    REQUIRE(in.dot(out) < std::cos(std::numbers::pi / 4));
  }
  REQUIRE(sharp_count == 1);
  REQUIRE_FALSE(c.sharp.front());
  REQUIRE_FALSE(c.sharp.back());
  require_g1_inside_sections(c);
}

TEST_CASE("smooth strokes have no sharp joints", "[preprocess][bezier_fit]") {
  std::mt19937_64 rng(79);
  const BezierFitParams params;
  const auto s = test::sample_path(test::arc(0.15, 4.0), 300, 0.001, 0.5, rng);
  REQUIRE(find_corners(s.points, params).empty());
  const Curve c = fit_poly_bezier(s.points, params);
  for (bool f : c.sharp) REQUIRE_FALSE(f);
}

TEST_CASE("fit handles minimal and degenerate input", "[preprocess][bezier_fit]") {
  const BezierFitParams params;
  const Curve two = fit_poly_bezier({Vec3::Zero(), Vec3(0.1, 0, 0)}, params);
  REQUIRE(validate(two).empty());
  REQUIRE(two.segment_count() == 1);
  const Curve dup = fit_poly_bezier({Vec3::Zero(), Vec3::Zero(), Vec3(0.1, 0, 0),
                                     Vec3(0.1, 0, 0), Vec3(0.2, 0.05, 0)},
                                    params);
  REQUIRE(validate(dup).empty());
  for (const Vec3& p : dup.control_points) REQUIRE(p.allFinite());
  REQUIRE_THROWS_AS(fit_poly_bezier({Vec3::Zero(), Vec3::Zero()}, params), std::invalid_argument);
  REQUIRE_THROWS_AS(fit_poly_bezier({}, params), std::invalid_argument);
  BezierFitParams bad;
  bad.tolerance = 0.0;
  REQUIRE_THROWS_AS(fit_poly_bezier({Vec3::Zero(), Vec3::UnitX()}, bad), std::invalid_argument);
}
