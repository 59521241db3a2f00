#pragma once
// A perspective view for the view and camera tests, and the distance of a
// point from a ray.
#include <numbers>

#include "sketchlab/view.hpp"

namespace sketchlab::test {

constexpr double test_fovy = std::numbers::pi / 3.0;

// Looking from `eye` at `target` (y up), 60° vertical field of view, aspect
// 1.5, a 1200 x 800 viewport whose corner is at pixel (10, 20).
inline View make_view(const Vec3& eye, const Vec3& target) {
  View v;
  v.view = look_at(eye, target, Vec3::UnitY());
  v.projection = perspective(test_fovy, 1.5, 0.1, 100.0);
  v.viewport = Vec4(10, 20, 1200, 800);
  return v;
}

inline double distance_to_ray(const Ray& r, const Vec3& p) {
  const Vec3 d = p - r.origin;
  return (d - d.dot(r.direction) * r.direction).norm();
}

}  // namespace sketchlab::test
