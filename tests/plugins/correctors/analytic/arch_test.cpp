// §3.2 / Figure 9b: a curve stroke over a square scaffold whose edges give
// the tangent directions is inferred as the planar, mirror-symmetric curve
// through the corners and the top midpoint.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "analytic_corrector.hpp"
#include "demo_scenes.hpp"
#include "sketchlab/geometry/bezier.hpp"

using namespace sketchlab;
using namespace sketchlab::analytic;

TEST_CASE("a curve over a square scaffold with tangent guidelines is planar and symmetric",
          "[analytic][curve]") {
  Sketch sketch;
  const Vec3 c0(0, 0, 0), c1(1, 0, 0), c2(1, 1, 0), c3(0, 1, 0), m0(0.5, 0, 0), m1(0.5, 1, 0);
  for (const auto& [a, b] : std::vector<std::pair<Vec3, Vec3>>{{c0, c1}, {c1, c2}, {c2, c3}, {c3, c0}, {m0, m1}})
    demo::add_curve(sketch, make_line(a, b), Layer::scaffold);
  const View view = demo::tablet_view(Vec3(1.6, 1.1, 2.6), Vec3(0.5, 0.45, 0));
  // The intended curve: a half ellipse from c0 over m1 to c1.
  std::vector<Vec3> arch;
  for (int i = 0; i <= 60; ++i) {
    const double phi = std::numbers::pi * i / 60;
    arch.push_back(Vec3(0.5 - 0.5 * std::cos(phi), std::sin(phi), 0));
  }
  const Stroke stroke = demo::projected_stroke(7, view, arch, 0.7, 9);
  AnalyticCorrector corrector{AnalyticParams{}};
  const Correction c = corrector.correct(stroke, sketch);
  REQUIRE(c.error.empty());
  REQUIRE(c.edit.curves_added.size() == 1);
  CHECK(c.stats.extra.at("curve") == 1);
  CHECK(c.stats.extra.at("planar") == 1);
  CHECK(c.stats.extra.at("symmetric") == 1);
  CHECK(c.stats.extra.at("curves_fitted") < c.stats.extra.at("combinations"));
  const Curve& curve = c.edit.curves_added[0].curve;
  CHECK((curve.control_points.front() - c0).norm() < 1e-12);
  CHECK((curve.control_points.back() - c1).norm() < 1e-12);
  // Planar: every control point in z = 0.
  for (const Vec3& p : curve.control_points) CHECK(std::abs(p.z()) < 1e-9);
  // Through the top midpoint, tangent to the top edge there.
  bool through_top = false;
  for (std::size_t i = 0; i < curve.control_points.size(); i += 3)
    if ((curve.control_points[i] - m1).norm() < 1e-9) {
      through_top = true;
      CHECK(std::abs(tangent(curve, static_cast<double>(i / 3)).y()) < 1e-9);
    }
  CHECK(through_top);
  // Tangent to the square's sides at the ends.
  CHECK(std::abs(tangent(curve, 0.0).x()) < 1e-9);
  CHECK(std::abs(tangent(curve, curve.t_max()).x()) < 1e-9);
  // Mirror symmetric about x = 0.5: c(T - t) = mirror(c(t)).
  for (int i = 0; i <= 50; ++i) {
    const double t = curve.t_max() * i / 50;
    const Vec3 p = evaluate(curve, t), q = evaluate(curve, curve.t_max() - t);
    CHECK((Vec3(1.0 - p.x(), p.y(), p.z()) - q).norm() < 1e-9);
  }
  // Close to the drawn half ellipse.
  for (const Vec3& p : arch) {
    double best = 1e9;
    for (int i = 0; i <= 400; ++i) best = std::min(best, (evaluate(curve, curve.t_max() * i / 400) - p).norm());
    CHECK(best < 0.03);
  }
}
