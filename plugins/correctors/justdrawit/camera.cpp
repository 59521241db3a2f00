#include "camera.hpp"

#include <Eigen/LU>
#include <stdexcept>

namespace sketchlab::justdrawit {

Camera::Camera(const View& view) : viewport_(view.viewport), view_(view.view) {
  pv_ = view.projection * view.view;
  Eigen::FullPivLU<Mat4> lu(pv_);
  if (!pv_.allFinite() || !lu.isInvertible())
    throw std::invalid_argument("justdrawit: the stroke's projection * view is not invertible");
  if (!(viewport_[2] > 0 && viewport_[3] > 0))
    throw std::invalid_argument("justdrawit: the stroke's viewport is empty");
  inv_ = lu.inverse();
  const Mat3 r = view.view.topLeftCorner<3, 3>();
  forward_ = (r.transpose() * Vec3(0, 0, -1)).normalized();
  Eigen::FullPivLU<Mat4> lv(view.view);
  eye_ = lv.isInvertible() ? Vec3((lv.inverse().col(3).head<3>())) : Vec3::Zero();
}

bool Camera::to_pixel(const Vec3& world, Vec2& pixel) const {
  const Vec4 clip = pv_ * world.homogeneous();
  if (!(clip.w() > 0)) return false;
  pixel = {viewport_[0] + (clip.x() / clip.w() + 1.0) * 0.5 * viewport_[2],
           viewport_[1] + (clip.y() / clip.w() + 1.0) * 0.5 * viewport_[3]};
  return pixel.allFinite();
}

Ray Camera::ray(const Vec2& pixel) const {
  const double x = 2.0 * (pixel.x() - viewport_[0]) / viewport_[2] - 1.0;
  const double y = 2.0 * (pixel.y() - viewport_[1]) / viewport_[3] - 1.0;
  const Vec4 n = inv_ * Vec4(x, y, -1.0, 1.0);
  const Vec4 f = inv_ * Vec4(x, y, 1.0, 1.0);
  const Vec3 a = n.head<3>() / n.w(), b = f.head<3>() / f.w();
  return {a, (b - a).normalized()};
}

double Camera::eye_depth(const Vec3& world) const {
  return -(view_ * world.homogeneous()).z();
}

double Camera::world_per_pixel(const Vec3& p) const {
  Vec2 px;
  if (!to_pixel(p, px)) return 1.0;
  const Plane pl = film_plane(p);
  const auto a = intersect(ray(px), pl), b = intersect(ray(px + Vec2(1, 0)), pl);
  if (!a || !b) return 1.0;
  const double w = (*b - *a).norm();
  return w > 0 && std::isfinite(w) ? w : 1.0;
}

std::optional<Vec3> intersect(const Ray& ray, const Plane& plane) {
  const double den = ray.direction.dot(plane.normal);
  if (std::abs(den) < 1e-12) return std::nullopt;
  const double t = (plane.point - ray.origin).dot(plane.normal) / den;
  return ray.origin + t * ray.direction;
}

std::optional<double> plane_depth(const Camera& cam, const Plane& plane, const Vec3& p) {
  Vec2 px;
  if (!cam.to_pixel(p, px)) return std::nullopt;
  const Ray r = cam.ray(px);
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
