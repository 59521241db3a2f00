#include "curve_tangent.hpp"

#include <algorithm>
#include <cmath>

#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab::soapfilm {

Vec3 one_sided_tangent(const Curve& curve, double t, bool after) {
  const int K = curve.segment_count();
  if (K == 0) return Vec3::UnitX();
  t = std::clamp(t, 0.0, static_cast<double>(K));
  int k = after ? static_cast<int>(std::floor(t)) : static_cast<int>(std::ceil(t)) - 1;
  k = std::clamp(k, 0, K - 1);
  const double u = std::clamp(t - k, 0.0, 1.0);
  const auto p = segment_points(curve, k);
  const Vec3 d = bezier_derivative(p, u);
  const double scale = std::max({(p[1] - p[0]).norm(), (p[2] - p[1]).norm(), (p[3] - p[2]).norm()});
  if (d.norm() > 1e-12 * scale && d.allFinite()) return d.normalized();
  // Vanishing derivative: direction of the nearest distinct control point.
  if (u < 0.5) {
    for (int i = 1; i < 4; ++i)
      if ((p[i] - p[0]).norm() > 1e-12 * scale) return (p[i] - p[0]).normalized();
  } else {
    for (int i = 2; i >= 0; --i)
      if ((p[3] - p[i]).norm() > 1e-12 * scale) return (p[3] - p[i]).normalized();
  }
  return Vec3::UnitX();
}

}  // namespace sketchlab::soapfilm
