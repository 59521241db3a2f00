#include "sketchlab/geometry/plane.hpp"

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

}  // namespace sketchlab
