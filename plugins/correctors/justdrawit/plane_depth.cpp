#include "plane_depth.hpp"

namespace sketchlab::justdrawit {

std::optional<double> plane_depth(const Camera& cam, const Plane& plane, const Vec3& p) {
  const auto px = cam.project(p);
  if (!px) return std::nullopt;
  const Ray r = cam.ray(*px);
  const auto q = intersect(r, plane);
  if (!q) return std::nullopt;
  return (p - *q).dot(r.direction);
}

std::optional<Vec3> at_depth(const Camera& cam, const Plane& plane, const Vec2& pixel, double depth) {
  const Ray r = cam.ray(pixel);
  const auto q = intersect(r, plane);
  if (!q) return std::nullopt;
  return *q + depth * r.direction;
}

}  // namespace sketchlab::justdrawit
