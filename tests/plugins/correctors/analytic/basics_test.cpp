// Parameters, bad input, free strokes and their re-inference (§2.1).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "analytic_params.hpp"
#include "sketchlab/camera.hpp"
#include "drawing.hpp"
#include "stroke_2d.hpp"

using namespace sketchlab;
using namespace sketchlab::analytic;

TEST_CASE("parameter specs carry the paper's defaults and validate", "[analytic]") {
  const Params p = validate_params(parameter_specs(), {});
  const AnalyticParams a = params_from(p);
  CHECK(a.v_max == 40.0);
  CHECK(a.delta_min == 0.1);
  CHECK(a.delta_max == 0.5);
  CHECK(a.k_r == 2.0);
  CHECK(a.lambda == 0.25);
  CHECK(a.r_kappa == 2.0);
  CHECK(std::abs(a.direction_spread - 10.0 * degrees) < 1e-15);
  CHECK_THROWS_AS(validate_params(parameter_specs(), {{"k_r", ParamValue{-1.0}}}), ParamError);
}

TEST_CASE("uncertainty radius follows eq. 3 in pixels", "[analytic]") {
  Stroke s;
  s.view = demo::tablet_view(Vec3(0, 1, 3), Vec3(0, 0, 0));
  s.samples_are_pixels = true;
  for (int i = 0; i < 5; ++i) {
    Sample smp;
    smp.position = Vec3(100 + 96.0 * 20 * 0.01 * i, 200, 0);  // 20 in/s at 96 dpi
    smp.time = 0.01 * i;
    s.samples.push_back(smp);
  }
  const Stroke2d s2 = make_stroke_2d(s, 96.0, AnalyticParams{});
  for (double d : s2.delta) CHECK(std::abs(d - (0.1 + 0.5 * 0.4) * 96.0) < 1e-9);  // Lerp(0.5, 0.1, 0.5) in
}

TEST_CASE("bad input gets a clear error or a free stroke, never NaN", "[analytic]") {
  AnalyticCorrector c{AnalyticParams{}};
  Sketch sketch;
  Stroke vr;
  vr.id = 1;
  vr.samples.resize(3);
  const Correction r = c.correct(vr, sketch);
  CHECK(r.error.find("2D") != std::string::npos);

  Stroke dot;
  dot.id = 2;
  dot.view = demo::tablet_view(Vec3(0, 1, 3), Vec3(0, 0, 0));
  dot.samples_are_pixels = true;
  dot.samples.resize(4);
  for (auto& smp : dot.samples) smp.position = Vec3(400, 300, 0);
  const Correction f = c.correct(dot, sketch);
  CHECK(f.error.empty());
  CHECK(f.edit.curves_added.empty());
  CHECK(f.stats.extra.at("free") == 1);

  Stroke singular = dot;
  singular.id = 3;
  singular.samples[1].position = Vec3(500, 300, 0);
  singular.view->projection = Mat4::Zero();
  CHECK(!c.correct(singular, sketch).error.empty());
}

TEST_CASE("a free stroke is re-inferred when geometry appears near it", "[analytic][free]") {
  const double th = 30.0 * std::numbers::pi / 180.0;
  const Vec3 d1(std::cos(th), 0, std::sin(th)), d2(-std::sin(th), 0, std::cos(th)), up = Vec3::UnitY();
  const Vec3 B0(-0.4, 0, -0.6), B1 = B0 + d1, B3 = B0 + 0.8 * d2;
  test::Drawing d(demo::tablet_view(Vec3(0.2, 0.8, 6.0), Vec3(0.2, 0.8, 0.0)));
  REQUIRE(test::stat(d.draw({B0, B1}), "line") == 1);
  // A vertical at a corner that does not exist yet: nothing to infer from.
  const StepReport free = d.draw({B3, B3 + 0.5 * up});
  CHECK(test::stat(free, "free") == 1);
  CHECK(test::stat(free, "free_strokes") == 1);
  // The edge to that corner: the free stroke now starts at a vertex.
  const StepReport edge = d.draw({B0, B3});
  CHECK(test::stat(edge, "line") == 1);
  CHECK(test::stat(edge, ("reinferred." + std::to_string(*free.stroke)).c_str()) == 1);
  CHECK(test::stat(edge, "free_strokes") == 0);
  const auto vertical = d.added_by(*free.stroke);
  REQUIRE(vertical.size() == 1);
  const Vec3 a = vertical[0].curve.control_points.front(), b = vertical[0].curve.control_points.back();
  CHECK(std::abs((b - a).normalized().dot(up)) > std::cos(0.1 * std::numbers::pi / 180.0));
  const auto edge_curves = d.added_by(*edge.stroke);
  REQUIRE(edge_curves.size() == 1);
  CHECK((a - edge_curves[0].curve.control_points.back()).norm() < 1e-9);
}
