#include "stroke_2d.hpp"

#include <algorithm>
#include <cmath>

#include "sketchlab/preprocess/hooks.hpp"

namespace sketchlab::analytic {

Stroke2d make_stroke_2d(const Stroke& stroke, double dpi, const AnalyticParams& p) {
  Stroke2d s;
  std::vector<double> times;
  for (const Sample& smp : stroke.samples) {
    const Vec2 q = smp.position.head<2>();
    if (!q.allFinite()) continue;
    if (!s.points.empty() && (q - s.points.back()).norm() < 1e-9) continue;
    s.points.push_back(q);
    times.push_back(smp.time);
  }
  if (p.remove_hooks && s.points.size() >= 2 && p.hook_max_length * dpi > 0) {
    // Hooks (a flick at pen-down/up, kernel's find_hookless_range) are cut
    // before anything reads the ends: eq. 3 scores the endpoints only, and a
    // hook moves one by its length and breaks the straightness test.
    std::vector<Vec3> pts;
    pts.reserve(s.points.size());
    for (const Vec2& q : s.points) pts.emplace_back(q.x(), q.y(), 0.0);
    HookParams hp;
    hp.max_length = p.hook_max_length * dpi;
    hp.min_length = std::min(p.hook_min_length * dpi, hp.max_length);
    hp.max_bend_ratio = p.hook_max_bend;
    const IndexRange r = find_hookless_range(pts, hp);
    if (r.first > 0 || r.last + 1 < s.points.size()) {
      s.points = std::vector<Vec2>(s.points.begin() + static_cast<std::ptrdiff_t>(r.first),
                                   s.points.begin() + static_cast<std::ptrdiff_t>(r.last) + 1);
      times = std::vector<double>(times.begin() + static_cast<std::ptrdiff_t>(r.first),
                                  times.begin() + static_cast<std::ptrdiff_t>(r.last) + 1);
      s.hooks_cut = true;
    }
  }
  const std::size_t n = s.points.size();
  std::vector<double> speed(n > 0 ? n - 1 : 0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double dt = times[i + 1] - times[i];
    const double d = (s.points[i + 1] - s.points[i]).norm();
    s.length += d;
    speed[i] = dt > 0 && std::isfinite(dt) ? d / dt / dpi : p.v_max;
  }
  s.delta.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    double v = p.v_max;
    if (!speed.empty()) {
      const double a = i > 0 ? speed[i - 1] : speed[i];
      const double b = i + 1 < n ? speed[i] : speed[i - 1];
      v = 0.5 * (a + b);
    }
    const double u = std::clamp(v / p.v_max, 0.0, 1.0);
    s.delta[i] = (p.delta_min + u * (p.delta_max - p.delta_min)) * dpi;
  }
  const std::size_t step = std::max<std::size_t>(1, n / 100);
  for (std::size_t i = 0; i < n; i += step) {
    s.coarse.push_back(s.points[i]);
    s.coarse_delta.push_back(s.delta[i]);
  }
  if (n > 0 && (n - 1) % step != 0) {
    s.coarse.push_back(s.points.back());
    s.coarse_delta.push_back(s.delta.back());
  }
  return s;
}

double segment_distance(const Vec2& q, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? std::clamp((q - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (a + t * ab - q).norm();
}

PolylineHit nearest_on_polyline(const std::vector<Vec2>& poly, const Vec2& q) {
  PolylineHit best;
  best.distance = poly.empty() ? 0.0 : (poly[0] - q).norm();
  double acc = 0.0;
  for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
    const Vec2 ab = poly[i + 1] - poly[i];
    const double l2 = ab.squaredNorm();
    const double t = l2 > 0 ? std::clamp((q - poly[i]).dot(ab) / l2, 0.0, 1.0) : 0.0;
    const double d = (poly[i] + t * ab - q).norm();
    if (d < best.distance) {
      best.distance = d;
      best.index = static_cast<int>(t < 0.5 ? i : i + 1);
      best.arclength = acc + t * std::sqrt(l2);
    }
    acc += std::sqrt(l2);
  }
  return best;
}

double chord_deviation(const std::vector<Vec2>& poly) {
  if (poly.size() < 3) return 0.0;
  double worst = 0.0;
  for (const Vec2& q : poly) worst = std::max(worst, segment_distance(q, poly.front(), poly.back()));
  return worst;
}

}  // namespace sketchlab::analytic
