#pragma once
// A camera for 2D input: OpenGL-style view and projection matrices plus the
// viewport in pixels. Pixel coordinates have their origin at the viewport's
// bottom-left corner (OpenGL window coordinates).
#include <string>

#include "sketchlab/types.hpp"

namespace sketchlab {

struct View {
  Mat4 view = Mat4::Identity();        // world -> eye
  Mat4 projection = Mat4::Identity();  // eye -> clip
  Vec4 viewport{0, 0, 1, 1};           // x, y, width, height in pixels
  double dpi = 96.0;                   // pixels per inch of the input surface

  bool operator==(const View& o) const {
    return view == o.view && projection == o.projection && viewport == o.viewport &&
           dpi == o.dpi;
  }
};

struct Ray {
  Vec3 origin;
  Vec3 direction;  // unit length
};

// World point -> (pixel x, pixel y, depth in [0,1]). Points behind the camera
// get a negative depth.
Vec3 world_to_pixel(const View& view, const Vec3& world);

// Empty when pixels of `view` can be turned into rays (a finite viewport of
// positive size, a finite and invertible projection * view), else the
// reason, e.g. "its camera (projection * view) is not invertible".
std::string view_problem(const View& view);

// Pixel -> world-space ray through that pixel (from the near plane). Throws
// std::invalid_argument for a view with a view_problem() or a non-finite
// pixel.
Ray pixel_to_ray(const View& view, const Vec2& pixel);

// The eye position in world coordinates.
Vec3 eye_position(const View& view);

// Standard perspective projection (right-handed, OpenGL clip conventions).
Mat4 perspective(double fovy_radians, double aspect, double z_near, double z_far);
// Right-handed look-at view matrix.
Mat4 look_at(const Vec3& eye, const Vec3& target, const Vec3& up);

}  // namespace sketchlab
