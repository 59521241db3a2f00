// The 2D stroke the inference reads: hooks at the ends are cut before eq. 3
// scores the endpoints; smooth bends are kept.
#include <catch2/catch.hpp>
#include <algorithm>
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

TEST_CASE("a curve's tight bend near its start is no hook", "[analytic][stroke2d]") {
  // Half of a flat ellipse (120 x 20 px, as a circle seen at a grazing
  // angle) drawn from 0.3 rad before its tip, sampled as the synthetic
  // tablet pen moves: minimum jerk along the arclength, 500 px/s, 120 Hz.
  // The tip turns by ~100° within ~15 px of the start, which CASSIE's hook
  // rule cuts; its piece before the cut bends with it, so it is kept.
  const int dense = 4000;
  std::vector<Vec2> path;
  std::vector<double> cum{0.0};
  for (int k = 0; k <= dense; ++k) {
    const double t = -0.3 + (std::numbers::pi + 0.3) * k / dense;
    path.emplace_back(120.0 * std::cos(t), 20.0 * std::sin(t));
    if (k > 0) cum.push_back(cum.back() + (path[k] - path[k - 1]).norm());
  }
  const int n = static_cast<int>(std::lround(cum.back() / 500.0 * 120.0)) + 1;
  std::vector<Vec2> pts;
  std::size_t j = 0;
  for (int i = 0; i < n; ++i) {
    const double u = static_cast<double>(i) / (n - 1);
    const double s = cum.back() * u * u * u * (10.0 - 15.0 * u + 6.0 * u * u);
    while (j + 1 < cum.size() - 1 && cum[j + 1] < s) ++j;
    const double f = std::clamp((s - cum[j]) / (cum[j + 1] - cum[j]), 0.0, 1.0);
    pts.push_back(path[j] + f * (path[j + 1] - path[j]));
  }
  const double dpi = 96.0;
  const Stroke2d kept = make_stroke_2d(pixel_stroke(pts), dpi, AnalyticParams{});
  CHECK_FALSE(kept.hooks_cut);
  CHECK((kept.points.front() - pts.front()).norm() < 1e-12);
  AnalyticParams any_bend;
  any_bend.hook_max_bend = 1.0;
  const Stroke2d cut = make_stroke_2d(pixel_stroke(pts), dpi, any_bend);
  CHECK(cut.hooks_cut);
}
