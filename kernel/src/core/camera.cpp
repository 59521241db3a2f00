#include "sketchlab/camera.hpp"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sketchlab {
namespace {

Vec2 to_window(const Vec4& vp, const Vec4& clip) {
  return {vp[0] + (clip.x() / clip.w() + 1.0) * 0.5 * vp[2], vp[1] + (clip.y() / clip.w() + 1.0) * 0.5 * vp[3]};
}

}  // namespace

Camera::Camera(const View& view) : view_(view) {
  if (const std::string why = view_problem(view); !why.empty())
    throw std::invalid_argument("Camera: " + why);
  pv_ = view.projection * view.view;
  inv_ = Eigen::FullPivLU<Mat4>(pv_).inverse();
  const Mat3 r = view.view.topLeftCorner<3, 3>();
  right_ = r.row(0).transpose().normalized();
  up_ = r.row(1).transpose().normalized();
  // The eye's -z axis in world space, computed as JustDrawIt always has
  // (-r.row(2) gives other last bits for some views, and so other sketches).
  forward_ = (r.transpose() * Vec3(0, 0, -1)).normalized();
}

std::optional<Vec2> Camera::project(const Vec3& world) const {
  const Vec4 clip = pv_ * world.homogeneous();
  if (!(clip.w() > 1e-12)) return std::nullopt;
  const Vec2 pixel = to_window(view_.viewport, clip);
  if (!pixel.allFinite()) return std::nullopt;
  return pixel;
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
  return to_window(view_.viewport, clip);
}

double Camera::eye_depth(const Vec3& world) const { return -(view_.view * world.homogeneous()).z(); }

double Camera::world_per_pixel(const Vec3& p) const {
  const auto px = project(p);
  if (!px) return 1.0;
  const Plane pl = film_plane(p);
  const auto a = intersect(ray(*px), pl), b = intersect(ray(*px + Vec2(1, 0)), pl);
  if (!a || !b) return 1.0;
  const double w = (*b - *a).norm();
  return w > 0 && std::isfinite(w) ? w : 1.0;
}

}  // namespace sketchlab
