#pragma once
// The stroke's View with its matrices inverted once (projecting every curve
// point per stroke must not redo a 4x4 inversion), plus the plane/depth
// conventions of §4.4.1.
#include <optional>

#include "point_list.hpp"
#include "sketchlab/view.hpp"

namespace sketchlab::justdrawit {

struct Plane {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit
};

class Camera {
 public:
  // Throws std::invalid_argument for a singular view/projection or an empty viewport.
  explicit Camera(const View& view);
  // World -> pixel; false when the point is on or behind the eye plane.
  bool to_pixel(const Vec3& world, Vec2& pixel) const;
  Ray ray(const Vec2& pixel) const;
  Vec3 forward() const { return forward_; }  // unit viewing direction (world)
  // Distance in front of the eye along forward() (the depth of eq. 6).
  double eye_depth(const Vec3& world) const;
  // The film plane (perpendicular to the view direction) through p.
  Plane film_plane(const Vec3& p) const { return {p, forward_}; }
  // World length of one pixel at p, measured on the film plane through p
  // (§4.5: d3 = d * world_per_pixel at the middle of the curves).
  double world_per_pixel(const Vec3& p) const;

 private:
  Mat4 pv_, inv_;
  Vec4 viewport_;
  Vec3 forward_;
  Vec3 eye_;
  Mat4 view_;
};

// Where the ray meets the plane (any ray parameter); nothing when parallel.
std::optional<Vec3> intersect(const Ray& ray, const Plane& plane);

// §4.4.1: the signed depth of p relative to the plane, measured along the
// camera ray through p (positive away from the camera). Nothing when the
// ray through p misses the plane or p is behind the eye.
std::optional<double> plane_depth(const Camera& cam, const Plane& plane, const Vec3& p);
// The point at `depth` along the ray through `pixel`, measured from the plane.
std::optional<Vec3> at_depth(const Camera& cam, const Plane& plane, const Vec2& pixel, double depth);

}  // namespace sketchlab::justdrawit
