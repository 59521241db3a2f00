#include "sketchlab/geometry/bounding_box.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab {
namespace {

// Extends box by segment p restricted to local [u0, u1]: ends plus the
// interior extrema of each coordinate, i.e. the roots of the quadratic
// derivative B'_i(u) = 3[(1-u)^2 d0 + 2u(1-u) d1 + u^2 d2].
void extend_segment(Box3& box, const std::array<Vec3, 4>& p, double u0, double u1) {
  box.extend(bezier_point(p, u0));
  box.extend(bezier_point(p, u1));
  for (int i = 0; i < 3; ++i) {
    const double d0 = p[1][i] - p[0][i];
    const double d1 = p[2][i] - p[1][i];
    const double d2 = p[3][i] - p[2][i];
    // In power basis: A u^2 + B u + C.
    const double A = d0 - 2.0 * d1 + d2;
    const double B = 2.0 * (d1 - d0);
    const double C = d0;
    std::array<double, 2> roots{};
    int n = 0;
    const double scale = std::max({std::abs(d0), std::abs(d1), std::abs(d2)});
    if (scale == 0.0) continue;
    if (std::abs(A) <= 1e-14 * scale) {
      if (B != 0.0) roots[n++] = -C / B;
    } else {
      const double disc = B * B - 4.0 * A * C;
      if (disc >= 0.0) {
        // Numerically stable quadratic formula.
        const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
        roots[n++] = q / A;
        if (q != 0.0) roots[n++] = C / q;
      }
    }
    for (int r = 0; r < n; ++r) {
      if (roots[r] > u0 && roots[r] < u1) box.extend(bezier_point(p, roots[r]));
    }
  }
}

}  // namespace

Box3 bounding_box(const Curve& curve) {
  require_segments(curve, "bounding_box");
  return bounding_box(curve, 0.0, curve.t_max());
}

Box3 bounding_box(const Curve& curve, double t0, double t1) {
  require_segments(curve, "bounding_box");
  if (!std::isfinite(t0) || !std::isfinite(t1) || t1 < t0) {
    throw std::invalid_argument("bounding_box: need finite t0 <= t1, got t0 = " +
                                std::to_string(t0) + ", t1 = " + std::to_string(t1));
  }
  const double tm = curve.t_max();
  t0 = std::clamp(t0, 0.0, tm);
  t1 = std::clamp(t1, 0.0, tm);
  Box3 box;
  box.setEmpty();
  const auto [k0, u0] = locate(curve, t0);
  const auto [k1, u1] = locate(curve, t1);
  for (int k = k0; k <= k1; ++k) {
    extend_segment(box, segment_points(curve, k), k == k0 ? u0 : 0.0, k == k1 ? u1 : 1.0);
  }
  return box;
}

}  // namespace sketchlab
