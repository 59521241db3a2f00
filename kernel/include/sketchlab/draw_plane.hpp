#pragma once
// 2D strokes drawn on a plane: lifting pixel samples onto the stroke's draw
// plane gives the 3D stroke that world-space correctors receive.
#include <string>

#include "sketchlab/stroke.hpp"
#include "sketchlab/types.hpp"

namespace sketchlab {

// The plane through `point` with unit normal `normal`, as (n, d) with n·x = d.
// Throws std::invalid_argument for a zero or non-finite normal or point.
Vec4 plane_through(const Vec3& point, const Vec3& normal);

// Where the ray through `pixel` of `view` meets `plane` ((n, d), |n| = 1);
// false when the ray is parallel to the plane or meets it behind the eye.
bool pixel_on_plane(const View& view, const Vec4& plane, const Vec2& pixel, Vec3& world);

// The stroke with every sample moved from its pixel onto the draw plane
// (samples_are_pixels false; view, draw plane, times, pressures kept).
// Strokes that are not 2D or have no draw plane are returned unchanged. On
// failure (a sample's ray misses the plane) returns the stroke unchanged and
// sets `error` to the reason naming the stroke and sample.
Stroke lift_to_draw_plane(const Stroke& stroke, std::string& error);

}  // namespace sketchlab
