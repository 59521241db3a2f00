#include "sketchlab/view.hpp"

#include <Eigen/LU>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sketchlab {

namespace {

void check_viewport(const View& view, const char* fn) {
  const Vec4& vp = view.viewport;
  if (!vp.allFinite() || !(vp[2] > 0.0) || !(vp[3] > 0.0)) {
    throw std::invalid_argument(std::string(fn) +
                                ": viewport width and height must be finite and > 0");
  }
}

Mat4 inverse_checked(const Mat4& m, const char* fn, const char* what) {
  Eigen::FullPivLU<Mat4> lu(m);
  if (!m.allFinite() || !lu.isInvertible()) {
    throw std::invalid_argument(std::string(fn) + ": " + what + " is not invertible");
  }
  return lu.inverse();
}

}  // namespace

std::string view_problem(const View& view) {
  const Vec4& vp = view.viewport;
  if (!vp.allFinite() || !(vp[2] > 0.0) || !(vp[3] > 0.0))
    return "its viewport width and height must be finite and > 0";
  const Mat4 m = view.projection * view.view;
  if (!m.allFinite() || !Eigen::FullPivLU<Mat4>(m).isInvertible())
    return "its camera (projection * view) is not invertible";
  return {};
}

Vec3 world_to_pixel(const View& view, const Vec3& world) {
  check_viewport(view, "world_to_pixel");
  const Vec4 clip = view.projection * view.view * world.homogeneous();
  const Vec4& vp = view.viewport;
  if (!(clip.w() > 0.0)) {
    // On or behind the eye plane: the projection is meaningless, report it by a
    // negative depth and keep the pixel finite.
    const double w = clip.w() == 0.0 ? 1.0 : -clip.w();
    return {vp[0] + (clip.x() / w + 1.0) * 0.5 * vp[2], vp[1] + (clip.y() / w + 1.0) * 0.5 * vp[3],
            -1.0};
  }
  const Vec3 ndc = clip.head<3>() / clip.w();
  return {vp[0] + (ndc.x() + 1.0) * 0.5 * vp[2], vp[1] + (ndc.y() + 1.0) * 0.5 * vp[3],
          (ndc.z() + 1.0) * 0.5};
}

Ray pixel_to_ray(const View& view, const Vec2& pixel) {
  check_viewport(view, "pixel_to_ray");
  if (!pixel.allFinite()) throw std::invalid_argument("pixel_to_ray: non-finite pixel");
  const Mat4 inv = inverse_checked(view.projection * view.view, "pixel_to_ray",
                                   "projection * view");
  const Vec4& vp = view.viewport;
  const double x = 2.0 * (pixel.x() - vp[0]) / vp[2] - 1.0;
  const double y = 2.0 * (pixel.y() - vp[1]) / vp[3] - 1.0;
  // Unproject the pixel on the near (z = -1) and far (z = 1) clip planes.
  const Vec4 n = inv * Vec4(x, y, -1.0, 1.0);
  const Vec4 f = inv * Vec4(x, y, 1.0, 1.0);
  if (n.w() == 0.0 || f.w() == 0.0) {
    throw std::invalid_argument("pixel_to_ray: degenerate projection (point at infinity)");
  }
  const Vec3 near_point = n.head<3>() / n.w();
  const Vec3 dir = f.head<3>() / f.w() - near_point;
  const double len = dir.norm();
  if (!(len > 0.0) || !std::isfinite(len)) {
    throw std::invalid_argument("pixel_to_ray: degenerate projection (near and far planes coincide)");
  }
  return {near_point, dir / len};
}

Vec3 eye_position(const View& view) {
  const Mat4 inv = inverse_checked(view.view, "eye_position", "the view matrix");
  const Vec4 e = inv.col(3);
  return e.head<3>() / e.w();
}

Mat4 perspective(double fovy_radians, double aspect, double z_near, double z_far) {
  if (!(fovy_radians > 0.0 && fovy_radians < std::numbers::pi)) {
    throw std::invalid_argument("perspective: fovy must be in (0, pi) radians, got " +
                                std::to_string(fovy_radians));
  }
  if (!(aspect > 0.0) || !std::isfinite(aspect)) {
    throw std::invalid_argument("perspective: aspect must be finite and > 0, got " +
                                std::to_string(aspect));
  }
  if (!(z_near > 0.0 && z_far > z_near) || !std::isfinite(z_far)) {
    throw std::invalid_argument("perspective: need 0 < z_near < z_far < inf, got " +
                                std::to_string(z_near) + ", " + std::to_string(z_far));
  }
  // gluPerspective.
  const double f = 1.0 / std::tan(fovy_radians / 2.0);
  Mat4 m = Mat4::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (z_far + z_near) / (z_near - z_far);
  m(2, 3) = 2.0 * z_far * z_near / (z_near - z_far);
  m(3, 2) = -1.0;
  return m;
}

Mat4 look_at(const Vec3& eye, const Vec3& target, const Vec3& up) {
  if (!eye.allFinite() || !target.allFinite() || !up.allFinite()) {
    throw std::invalid_argument("look_at: non-finite eye, target or up");
  }
  const Vec3 fwd = target - eye;
  if (!(fwd.norm() > 0.0)) throw std::invalid_argument("look_at: eye and target coincide");
  const Vec3 f = fwd.normalized();
  const Vec3 side = f.cross(up);
  if (!(side.norm() > 1e-12 * up.norm()) || !(up.norm() > 0.0)) {
    throw std::invalid_argument("look_at: up is zero or parallel to the view direction");
  }
  const Vec3 s = side.normalized();
  const Vec3 u = s.cross(f);
  // gluLookAt: rows are the camera axes; the camera looks down -z.
  Mat4 m = Mat4::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

}  // namespace sketchlab
