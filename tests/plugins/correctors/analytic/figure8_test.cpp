// Figure 8 of Schmidt et al. 2009: a stroke up from a box corner whose end
// also projects onto a ground-plane vertex is embedded in the ground plane
// (ambiguous, reported by the F(l1)/F(l0) ratio); two guidelines through the
// intended top corner make the same stroke a vertical edge.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "analytic_corrector.hpp"
#include "demo_scenes.hpp"
#include "drawing.hpp"

using namespace sketchlab;
using namespace sketchlab::analytic;

namespace {

Correction apply(AnalyticCorrector& c, Sketch& sketch, const Stroke& s) {
  sketch.strokes[s.id] = s;
  Correction r = c.correct(s, sketch);
  REQUIRE(r.error.empty());
  sketch.network.apply(r.edit);
  sketch.history.done.push_back(HistoryEntry{"stroke", s.id, {}});
  return r;
}

}  // namespace

TEST_CASE("Figure 8: the ambiguous diagonal becomes vertical once guidelines are added",
          "[analytic][figure8]") {
  const double th = 25.0 * std::numbers::pi / 180.0;
  const Vec3 d1(std::cos(th), 0, std::sin(th)), d2(-std::sin(th), 0, std::cos(th)), up = Vec3::UnitY();
  const double L1 = 0.8, L2 = 0.7, h = 0.5;
  const Vec3 B0(-0.3, 0, -0.4), B1 = B0 + L1 * d1, B3 = B0 + L2 * d2, B2 = B1 + L2 * d2;
  const Vec3 T0 = B0 + h * up, T1 = B1 + h * up, T3 = B3 + h * up;
  const View view = demo::tablet_view(Vec3(0.2, 1.6, 3.2), Vec3(0.1, 0.2, -0.3));
  // The ground point whose projection coincides with the top corner's.
  const Ray ray = pixel_to_ray(view, world_to_pixel(view, T0).head<2>());
  const Vec3 V = ray.origin + (-ray.origin.y() / ray.direction.y()) * ray.direction;
  REQUIRE((V - B0).norm() > 0.2);

  Sketch sketch;
  for (const auto& [a, b] : std::vector<std::pair<Vec3, Vec3>>{
           {B0, B1}, {B1, B2}, {B2, B3}, {B3, B0}, {B1, T1}, {B3, T3}, {B1, V}})
    demo::add_curve(sketch, make_line(a, b), Layer::scaffold);
  AnalyticCorrector corrector{AnalyticParams{}};

  const Stroke stroke = demo::projected_stroke(100, view, {B0, T0}, 0.5, 3);
  const Correction before = corrector.correct(stroke, sketch);
  REQUIRE(before.edit.curves_added.size() == 1);
  const Curve& diag = before.edit.curves_added[0].curve;
  // Embedded in the ground plane, ending on the ground vertex V.
  CHECK(std::abs(diag.control_points.front().y()) < 1e-9);
  CHECK(std::abs(diag.control_points.back().y()) < 1e-9);
  CHECK((diag.control_points.back() - V).norm() < 1e-9);
  const double ambiguity = before.stats.extra.at("confidence");
  CHECK(ambiguity > 0.1);  // a real competitor: the vertical
  CHECK(ambiguity < 1.0);

  // Two guidelines through the top corner (from the tops of the other verticals).
  for (const auto& [o, dir] : std::vector<std::pair<Vec3, Vec3>>{{T1, -d1}, {T3, -d2}}) {
    const Stroke g = demo::projected_stroke(sketch.network.next_curve_id() + 200, view,
                                            demo::guideline_path(view, o, dir), 0.5, 5);
    const Correction r = apply(corrector, sketch, g);
    REQUIRE(r.stats.extra.count("guideline"));
  }
  Stroke again = stroke;
  again.id = 101;
  const Correction after = corrector.correct(again, sketch);
  REQUIRE(after.edit.curves_added.size() == 1);
  const Curve& vert = after.edit.curves_added[0].curve;
  const Vec3 a = vert.control_points.front(), b = vert.control_points.back();
  CHECK((a - B0).norm() < 1e-9);
  CHECK((b - T0).norm() < 1e-9);
  CHECK(std::abs((b - a).normalized().dot(up)) > std::cos(0.1 * std::numbers::pi / 180.0));
  CHECK(after.stats.extra.at("confidence") < 1.0);
}
