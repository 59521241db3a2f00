#include "camera.hpp"

#include <Eigen/LU>
#include <stdexcept>

namespace sketchlab::analytic {

Camera::Camera(const View& view) : view_(view) {
  pv_ = view.projection * view.view;
  Eigen::FullPivLU<Mat4> lu(pv_);
  if (!pv_.allFinite() || !lu.isInvertible())
    throw std::invalid_argument("analytic: the stroke's view has a singular projection * view");
  const Vec4& vp = view.viewport;
  if (!vp.allFinite() || !(vp[2] > 0) || !(vp[3] > 0))
    throw std::invalid_argument("analytic: the stroke's viewport must have width and height > 0");
  inv_ = lu.inverse();
  const Mat3 r = view.view.block<3, 3>(0, 0);
  right_ = r.row(0).transpose().normalized();
  up_ = r.row(1).transpose().normalized();
  forward_ = -r.row(2).transpose().normalized();
}

std::optional<Vec2> Camera::project(const Vec3& world) const {
  const Vec4 clip = pv_ * world.homogeneous();
  if (!(clip.w() > 1e-12)) return std::nullopt;
  const Vec4& vp = view_.viewport;
  return Vec2(vp[0] + (clip.x() / clip.w() + 1.0) * 0.5 * vp[2],
              vp[1] + (clip.y() / clip.w() + 1.0) * 0.5 * vp[3]);
}

Ray Camera::ray(const Vec2& pixel) const {
  const Vec4& vp = view_.viewport;
  const double x = 2.0 * (pixel.x() - vp[0]) / vp[2] - 1.0;
  const double y = 2.0 * (pixel.y() - vp[1]) / vp[3] - 1.0;
  const Vec4 n = inv_ * Vec4(x, y, -1.0, 1.0);
  const Vec4 f = inv_ * Vec4(x, y, 1.0, 1.0);
  const Vec3 a = n.head<3>() / n.w();
  const Vec3 b = f.head<3>() / f.w();
  return {a, (b - a).normalized()};
}

std::optional<Vec2> Camera::vanishing_point(const Vec3& d) const {
  const Vec4 clip = pv_ * Vec4(d.x(), d.y(), d.z(), 0.0);
  if (std::abs(clip.w()) < 1e-9 * clip.head<2>().norm() || clip.w() == 0.0) return std::nullopt;
  const Vec4& vp = view_.viewport;
  return Vec2(vp[0] + (clip.x() / clip.w() + 1.0) * 0.5 * vp[2],
              vp[1] + (clip.y() / clip.w() + 1.0) * 0.5 * vp[3]);
}

}  // namespace sketchlab::analytic
