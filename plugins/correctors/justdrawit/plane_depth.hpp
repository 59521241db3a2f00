#pragma once
// The plane/depth conventions of §4.4.1: a point's depth relative to a plane,
// measured along the camera ray through it. The camera (sketchlab/camera.hpp)
// and the plane type (sketchlab/geometry/plane.hpp) are the kernel's.
#include <optional>

#include "point_list.hpp"
#include "sketchlab/camera.hpp"
#include "sketchlab/geometry/plane.hpp"

namespace sketchlab::justdrawit {

// §4.4.1: the signed depth of p relative to the plane, measured along the
// camera ray through p (positive away from the camera). Nothing when the
// ray through p misses the plane or p is behind the eye.
std::optional<double> plane_depth(const Camera& cam, const Plane& plane, const Vec3& p);
// The point at `depth` along the ray through `pixel`, measured from the plane.
std::optional<Vec3> at_depth(const Camera& cam, const Plane& plane, const Vec2& pixel, double depth);

}  // namespace sketchlab::justdrawit
