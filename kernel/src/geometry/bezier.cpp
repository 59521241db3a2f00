#include "sketchlab/geometry/bezier.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sketchlab {

std::pair<int, double> locate(const Curve& curve, double t) {
  const int k_count = curve.segment_count();
  if (k_count < 1) {
    throw std::invalid_argument("locate: curve has " +
                                std::to_string(curve.control_points.size()) +
                                " control points; need 3K+1 with K >= 1");
  }
  if (!std::isfinite(t)) throw std::invalid_argument("locate: parameter t is not finite");
  t = std::clamp(t, 0.0, static_cast<double>(k_count));
  int k = static_cast<int>(std::floor(t));
  if (k >= k_count) k = k_count - 1;
  return {k, t - static_cast<double>(k)};
}

std::array<Vec3, 4> segment_points(const Curve& curve, int k) {
  if (k < 0 || k >= curve.segment_count()) {
    throw std::out_of_range("segment_points: segment " + std::to_string(k) + " not in [0, " +
                            std::to_string(curve.segment_count()) + ")");
  }
  const auto& p = curve.control_points;
  const std::size_t i = 3 * static_cast<std::size_t>(k);
  return {p[i], p[i + 1], p[i + 2], p[i + 3]};
}

std::pair<std::array<Vec3, 4>, std::array<Vec3, 4>> bezier_subdivide(const std::array<Vec3, 4>& p, double u) {
  // De Casteljau: numerically stable and exact at u = 0 and u = 1.
  const double v = 1.0 - u;
  const Vec3 a = v * p[0] + u * p[1];
  const Vec3 b = v * p[1] + u * p[2];
  const Vec3 c = v * p[2] + u * p[3];
  const Vec3 d = v * a + u * b;
  const Vec3 e = v * b + u * c;
  const Vec3 f = v * d + u * e;
  return {{p[0], a, d, f}, {f, e, c, p[3]}};
}

Vec3 bezier_point(const std::array<Vec3, 4>& p, double u) { return bezier_subdivide(p, u).first[3]; }

Vec3 bezier_derivative(const std::array<Vec3, 4>& p, double u) {
  const double v = 1.0 - u;
  const Vec3 d0 = p[1] - p[0];
  const Vec3 d1 = p[2] - p[1];
  const Vec3 d2 = p[3] - p[2];
  return 3.0 * (v * v * d0 + 2.0 * u * v * d1 + u * u * d2);
}

namespace {

Vec3 bezier_second_derivative(const std::array<Vec3, 4>& p, double u) {
  const Vec3 a = p[2] - 2.0 * p[1] + p[0];
  const Vec3 b = p[3] - 2.0 * p[2] + p[1];
  return 6.0 * ((1.0 - u) * a + u * b);
}

}  // namespace

Vec3 evaluate(const Curve& curve, double t) {
  const auto [k, u] = locate(curve, t);
  return bezier_point(segment_points(curve, k), u);
}

Vec3 derivative(const Curve& curve, double t) {
  const auto [k, u] = locate(curve, t);
  return bezier_derivative(segment_points(curve, k), u);
}

Vec3 second_derivative(const Curve& curve, double t) {
  const auto [k, u] = locate(curve, t);
  return bezier_second_derivative(segment_points(curve, k), u);
}

Vec3 tangent(const Curve& curve, double t) {
  const auto [k, u] = locate(curve, t);
  const auto p = segment_points(curve, k);
  const double scale = std::max({(p[1] - p[0]).norm(), (p[2] - p[1]).norm(),
                                 (p[3] - p[2]).norm(), 1e-300});
  const Vec3 d = bezier_derivative(p, u);
  if (d.norm() > 1e-12 * scale) return d.normalized();
  // The derivative vanishes where control points coincide. The limit tangent
  // at an end is the direction to the first distinct control point; inside
  // the segment (or if that fails) use the chord.
  if (u < 0.5) {
    for (int i = 1; i < 4; ++i) {
      const Vec3 c = p[i] - p[0];
      if (c.norm() > 1e-12 * scale) return c.normalized();
    }
  } else {
    for (int i = 2; i >= 0; --i) {
      const Vec3 c = p[3] - p[i];
      if (c.norm() > 1e-12 * scale) return c.normalized();
    }
  }
  const Vec3 chord = curve.control_points.back() - curve.control_points.front();
  if (chord.norm() > 0.0) return chord.normalized();
  // Fully degenerate curve (a point): any unit vector keeps callers NaN-free.
  return Vec3::UnitX();
}

}  // namespace sketchlab
