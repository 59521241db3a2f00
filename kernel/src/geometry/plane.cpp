#include "sketchlab/geometry/plane.hpp"

#include <algorithm>
#include <cmath>

namespace sketchlab {

Plane plane_from_coefficients(const Vec4& coefficients) {
  return Plane{coefficients[3] * coefficients.head<3>(), coefficients.head<3>().normalized()};
}

std::optional<Vec3> intersect(const Ray& ray, const Plane& plane) {
  const double den = ray.direction.dot(plane.normal);
  if (std::abs(den) < 1e-12) return std::nullopt;
  const double t = (plane.point - ray.origin).dot(plane.normal) / den;
  return ray.origin + t * ray.direction;
}

double plane_residual(const std::vector<Vec3>& points, const Vec3& n) {
  if (points.empty()) return 0.0;
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : points) c += p;
  c /= static_cast<double>(points.size());
  double r = 0.0;
  for (const Vec3& p : points) r = std::max(r, std::abs((p - c).dot(n)));
  return r;
}

}  // namespace sketchlab
