// Figure 10a of Schmidt et al. 2009: a helix drawn in one stroke over a
// scaffold of points a quarter turn apart with tangent guidelines is inferred
// through every point with every tangent; branch-and-bound (§3.2) fits a
// small fraction of the combinations it generates and picks the same curve as
// exhaustive search.
#include <catch2/catch.hpp>

#include "analytic_corrector.hpp"
#include "demo_scenes.hpp"
#include "sketchlab/geometry/bezier.hpp"

using namespace sketchlab;
using namespace sketchlab::analytic;

namespace {

Correction draw_helix(int points, const AnalyticParams& params = AnalyticParams{}) {
  Sketch sketch;
  demo::add_helix_scaffold(sketch, points);
  const View view = demo::tablet_view(Vec3(2.2, 1.6, 2.6), Vec3(0, 0.6, 0));
  const Stroke s = demo::projected_stroke(1, view, demo::helix_polyline(points), 0.7, 3);
  AnalyticCorrector corrector{params};
  return corrector.correct(s, sketch);
}

void check_helix(const Correction& c, int points) {
  REQUIRE(c.error.empty());
  REQUIRE(c.edit.curves_added.size() == 1);
  const Curve& curve = c.edit.curves_added[0].curve;
  REQUIRE(curve.segment_count() == points - 1);
  const auto pts = demo::helix_points(points);
  for (int k = 0; k < points; ++k) {
    CHECK((curve.control_points[static_cast<std::size_t>(3 * k)] - pts[static_cast<std::size_t>(k)]).norm() < 1e-12);
    CHECK(tangent(curve, k).cross(demo::helix_tangent(k)).norm() < 1e-9);
  }
  // Close to the intended helix between the points too.
  for (const Vec3& p : demo::helix_polyline(points)) {
    double best = 1e9;
    for (int i = 0; i <= 60 * (points - 1); ++i)
      best = std::min(best, (evaluate(curve, curve.t_max() * i / (60.0 * (points - 1))) - p).norm());
    CHECK(best < 0.03);
  }
}

}  // namespace

TEST_CASE("5-point helix: inferred, and most combinations are never fitted", "[analytic][helix]") {
  const Correction c = draw_helix(5);
  check_helix(c, 5);
  const double combos = c.stats.extra.at("combinations"), fitted = c.stats.extra.at("curves_fitted");
  CHECK(combos > 100);
  CHECK(fitted < 0.2 * combos);
  CHECK(c.stats.extra.at("confidence") < 1.0);
}

TEST_CASE("9-point helix of Figure 10a: inferred through every point with every tangent",
          "[analytic][helix][slow]") {
  const Correction c = draw_helix(9);
  check_helix(c, 9);
  const double combos = c.stats.extra.at("combinations"), fitted = c.stats.extra.at("curves_fitted");
  CHECK(combos > 5000);
  CHECK(fitted <= 0.1 * combos);
  CHECK(c.stats.extra.at("g_bound_exceeded") == 0);
}

// The G bound (curve_g_slack) is not strictly admissible: on both helices
// branch-and-bound must return exactly the exhaustive search's winner.
void check_same_as_exhaustive(int points) {
  const Correction bb = draw_helix(points);
  AnalyticParams all;
  all.curve_exhaustive = true;
  const Correction ex = draw_helix(points, all);
  REQUIRE(bb.edit.curves_added.size() == 1);
  REQUIRE(ex.edit.curves_added.size() == 1);
  CHECK(ex.stats.extra.at("curves_fitted") > 0.9 * ex.stats.extra.at("combinations"));
  CHECK(bb.stats.extra.at("curves_fitted") < 0.2 * ex.stats.extra.at("curves_fitted"));
  CHECK(bb.stats.extra.at("fitness") == Approx(ex.stats.extra.at("fitness")).epsilon(1e-12));
  const auto& a = bb.edit.curves_added[0].curve.control_points;
  const auto& b = ex.edit.curves_added[0].curve.control_points;
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) CHECK((a[i] - b[i]).norm() < 1e-12);
}

TEST_CASE("5-point helix: branch-and-bound picks the exhaustive search's curve", "[analytic][helix]") {
  check_same_as_exhaustive(5);
}

TEST_CASE("9-point helix: branch-and-bound picks the exhaustive search's curve",
          "[analytic][helix][slow]") {
  check_same_as_exhaustive(9);
}
