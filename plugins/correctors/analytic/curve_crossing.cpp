#include "curve_crossing.hpp"

#include <cmath>
#include <optional>

#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab::analytic {

std::vector<CurveCrossing> curve_line_crossings(const Curve& curve, const Camera& cam, const Vec2& a,
                                                const Vec2& b, const Vec2& near, double radius,
                                                int samples_per_segment) {
  std::vector<CurveCrossing> out;
  if (!validate(curve).empty() || !((b - a).norm() >= 1e-9) || !(radius >= 0)) return out;
  const Vec2 dir = (b - a).normalized();
  const Vec2 normal(-dir.y(), dir.x());
  auto signed_distance = [&](double t, Vec2* pixel) -> std::optional<double> {
    const auto q = cam.project(evaluate(curve, t));
    if (!q || !q->allFinite()) return std::nullopt;
    if (pixel) *pixel = *q;
    return normal.dot(*q - a);
  };
  const int n = std::max(1, samples_per_segment) * curve.segment_count();
  const double t_max = curve.t_max();
  auto t_at = [&](int i) { return t_max * static_cast<double>(i) / n; };
  std::optional<double> prev = signed_distance(0.0, nullptr);
  for (int i = 1; i <= n; ++i) {
    const std::optional<double> cur = signed_distance(t_at(i), nullptr);
    if (prev && cur && ((*prev <= 0 && *cur > 0) || (*prev >= 0 && *cur < 0) || (i == n && *cur == 0))) {
      // Bisection keeps the bracket [lo, hi] with a sign change of the
      // distance; 60 halvings reach double precision in t.
      double lo = t_at(i - 1), hi = t_at(i), flo = *prev;
      double t = hi;
      if (flo == 0) {
        t = lo;
      } else if (*cur != 0) {
        for (int k = 0; k < 60 && hi - lo > 0; ++k) {
          const double mid = 0.5 * (lo + hi);
          const std::optional<double> fm = signed_distance(mid, nullptr);
          if (!fm) break;
          if (*fm != 0 && (*fm < 0) == (flo < 0)) {
            lo = mid;
            flo = *fm;
          } else {
            hi = mid;
          }
        }
        t = hi;
      }
      CurveCrossing c;
      c.t = t;
      c.point = evaluate(curve, t);
      Vec2 px;
      if (signed_distance(t, &px) && (px - near).norm() <= radius && c.point.allFinite()) {
        c.pixel = px;
        if (out.empty() || std::abs(out.back().t - t) > 1e-12) out.push_back(c);
      }
    }
    prev = cur;
  }
  return out;
}

}  // namespace sketchlab::analytic
