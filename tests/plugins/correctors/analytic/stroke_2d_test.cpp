// The 2D stroke the inference reads: hooks at the ends are cut before eq. 3
// scores the endpoints; smooth bends are kept.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "stroke_2d.hpp"

using namespace sketchlab;
using namespace sketchlab::analytic;

namespace {

Stroke pixel_stroke(const std::vector<Vec2>& points) {
  Stroke s;
  s.id = 1;
  s.samples_are_pixels = true;
  for (std::size_t i = 0; i < points.size(); ++i) {
    Sample smp;
    smp.position = Vec3(points[i].x(), points[i].y(), 0.0);
    smp.time = 0.01 * static_cast<double>(i);
    s.samples.push_back(smp);
  }
  return s;
}

}  // namespace

TEST_CASE("a hook at a stroke's end is cut, a smooth bend is not", "[analytic][stroke2d]") {
  const double dpi = 96.0;
  // A 200 px line along x, then an 8 px flick turning back by 135°.
  std::vector<Vec2> pts;
  for (int i = 0; i <= 50; ++i) pts.emplace_back(4.0 * i, 0.0);
  const Vec2 end = pts.back();
  const double a = 0.75 * std::numbers::pi;
  for (int i = 1; i <= 8; ++i) pts.push_back(end + static_cast<double>(i) * Vec2(std::cos(a), std::sin(a)));
  AnalyticParams p;
  const Stroke2d cut = make_stroke_2d(pixel_stroke(pts), dpi, p);
  CHECK(cut.hooks_cut);
  CHECK((cut.points.back() - end).norm() < 1e-12);
  CHECK((cut.points.front() - pts.front()).norm() < 1e-12);
  CHECK(cut.delta.size() == cut.points.size());

  p.remove_hooks = false;
  const Stroke2d kept = make_stroke_2d(pixel_stroke(pts), dpi, p);
  CHECK_FALSE(kept.hooks_cut);
  CHECK((kept.points.back() - pts.back()).norm() < 1e-12);

  // A quarter circle of radius 150 px turns smoothly: nothing is cut.
  std::vector<Vec2> arc;
  for (int i = 0; i <= 60; ++i) {
    const double t = 0.5 * std::numbers::pi * i / 60.0;
    arc.emplace_back(150.0 * std::cos(t), 150.0 * std::sin(t));
  }
  const Stroke2d smooth = make_stroke_2d(pixel_stroke(arc), dpi, AnalyticParams{});
  CHECK_FALSE(smooth.hooks_cut);
  CHECK(smooth.points.size() == arc.size());
}
