#pragma once
// Synthetic 2D drawings for the tests and the benchmark: a tablet camera,
// strokes that are exact projections of 3D polylines (plus optional pixel
// noise), and scaffolds built directly in a network.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "sketchlab/network_curve.hpp"
#include "sketchlab/sketch.hpp"
#include "sketchlab/view.hpp"

namespace sketchlab::analytic::demo {

// 35° vertical field of view, 1600×1000 px, 96 dpi.
inline View tablet_view(const Vec3& eye, const Vec3& target, const Vec3& up = Vec3::UnitY()) {
  View v;
  v.view = look_at(eye, target, up);
  v.projection = perspective(35.0 * std::numbers::pi / 180.0, 1.6, 0.05, 200.0);
  v.viewport = Vec4(0, 0, 1600, 1000);
  v.dpi = 96.0;
  return v;
}

// A stroke through the projections of `points` (a 3D polyline densified to
// ~`spacing` px), drawn at `speed` px/s, with isotropic Gaussian pixel noise
// of deviation `noise` (seeded).
inline Stroke projected_stroke(StrokeId id, const View& view, const std::vector<Vec3>& points,
                               double noise = 0.0, std::uint64_t seed = 1, double speed = 960.0,
                               double spacing = 4.0, Layer layer = Layer::automatic) {
  Stroke s;
  s.id = id;
  s.layer = layer;
  s.view = view;
  s.samples_are_pixels = true;
  std::mt19937_64 rng(seed * 7919 + id);
  std::normal_distribution<double> n(0.0, noise > 0 ? noise : 1.0);
  double t = 0.0;
  Vec2 last = Vec2::Zero();
  bool first = true;
  for (std::size_t i = 0; i + 1 < points.size() || (i == 0 && points.size() == 1); ++i) {
    const Vec3 a = points[i], b = points[std::min(i + 1, points.size() - 1)];
    const Vec3 pa = world_to_pixel(view, a), pb = world_to_pixel(view, b);
    const int steps = std::max(1, static_cast<int>(std::ceil((pb - pa).head<2>().norm() / spacing)));
    for (int k = 0; k <= steps; ++k) {
      if (k == 0 && !first) continue;
      const Vec3 w = a + (b - a) * (static_cast<double>(k) / steps);
      Vec2 q = world_to_pixel(view, w).head<2>();
      if (!first) t += (q - last).norm() / speed;
      last = q;
      first = false;
      if (noise > 0) q += Vec2(n(rng), n(rng));
      Sample smp;
      smp.position = Vec3(q.x(), q.y(), 0.0);
      smp.time = t;
      s.samples.push_back(smp);
    }
  }
  return s;
}

// A guideline stroke's 3D path: from `origin` along `dir` until its
// projection is 2 px inside the viewport border (or, toward an on-screen
// vanishing point, far enough to end on it).
inline std::vector<Vec3> guideline_path(const View& view, const Vec3& origin, const Vec3& dir) {
  auto inside = [&](double s) {
    const Vec3 q = world_to_pixel(view, origin + s * dir);
    const Vec4& vp = view.viewport;
    return q.z() >= 0 && q.x() >= vp[0] + 2 && q.x() <= vp[0] + vp[2] - 2 && q.y() >= vp[1] + 2 &&
           q.y() <= vp[1] + vp[3] - 2;
  };
  double lo = 0.0, hi = 0.01;
  while (inside(hi) && hi < 1e4) {
    lo = hi;
    hi *= 2;
  }
  if (hi >= 1e4) return {origin, origin + lo * dir};
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (inside(mid) ? lo : hi) = mid;
  }
  return {origin, origin + lo * dir};
}

inline std::vector<Vec3> segment(const Vec3& a, const Vec3& b) { return {a, b}; }

// Adds a curve to the network directly (scaffold built by hand).
inline CurveId add_curve(Sketch& sketch, const Curve& c, Layer layer) {
  const NetworkCurve nc = make_network_curve(sketch.network.next_curve_id(), c, layer);
  Edit e;
  e.curves_added.push_back(nc);
  sketch.network.apply(e);
  return nc.id;
}

// The helix of Figure 10a: `count` points a quarter turn apart on a helix of
// radius r and pitch h per turn around the vertical axis, each with a
// tangent guideline (an infinite line from the point, so only the points
// themselves are scaffold vertices).
inline std::vector<Vec3> helix_points(int count, double r = 0.5, double h = 0.6) {
  std::vector<Vec3> pts;
  for (int k = 0; k < count; ++k) {
    const double phi = k * std::numbers::pi / 2;
    pts.push_back(Vec3(r * std::cos(phi), 0.1 + h * k / 4.0, r * std::sin(phi)));
  }
  return pts;
}
inline Vec3 helix_tangent(int k, double r = 0.5, double h = 0.6) {
  const double phi = k * std::numbers::pi / 2;
  return Vec3(-r * std::sin(phi), h / (2 * std::numbers::pi), r * std::cos(phi)).normalized();
}
inline Vec3 helix_at(double phi, double r = 0.5, double h = 0.6) {
  return Vec3(r * std::cos(phi), 0.1 + h * phi / (2 * std::numbers::pi), r * std::sin(phi));
}
inline void add_helix_scaffold(Sketch& sketch, int count, double r = 0.5, double h = 0.6) {
  const auto pts = helix_points(count, r, h);
  for (int k = 0; k < count; ++k) {
    const Vec3 t = helix_tangent(k, r, h);
    add_curve(sketch, make_line(pts[static_cast<std::size_t>(k)], pts[static_cast<std::size_t>(k)] + 0.3 * t),
              Layer::guide);
  }
}
// A dense polyline of the helix through the first `count` points.
inline std::vector<Vec3> helix_polyline(int count, double r = 0.5, double h = 0.6) {
  std::vector<Vec3> out;
  const double end = (count - 1) * std::numbers::pi / 2;
  const int n = 40 * (count - 1);
  for (int i = 0; i <= n; ++i) out.push_back(helix_at(end * i / n, r, h));
  return out;
}

}  // namespace sketchlab::analytic::demo
