#pragma once
// A View (view.hpp) with its matrices multiplied and inverted once, for the
// many projections and rays a 2D corrector makes per stroke (the free
// functions of view.hpp redo a 4x4 inversion on every call). Pixels are the
// View's window coordinates (origin at the viewport's bottom-left corner);
// world positions in metres. Shared by the analytic drawing and JustDrawIt
// correctors.
#include <optional>

#include "sketchlab/geometry/plane.hpp"
#include "sketchlab/view.hpp"

namespace sketchlab {

class Camera {
 public:
  // Throws std::invalid_argument "Camera: <view_problem(view)>" for a view
  // whose pixels cannot be turned into rays (a non-finite or empty viewport,
  // a singular or non-finite projection * view).
  explicit Camera(const View& view);

  // Pixel of a world point; nothing when the point is on, behind or within
  // 1e-12 (clip w) of the eye plane, or the pixel is not finite.
  std::optional<Vec2> project(const Vec3& world) const;
  // Ray through a pixel: origin on the near plane, unit direction.
  Ray ray(const Vec2& pixel) const;
  // Pixel the direction d converges to (its vanishing point); nothing when d
  // is parallel to the image plane (vanishing point at infinity).
  std::optional<Vec2> vanishing_point(const Vec3& d) const;

  // Image-plane axes in world space (right, up) and the unit viewing
  // direction, from the rows of the view matrix.
  Vec3 right() const { return right_; }
  Vec3 up() const { return up_; }
  Vec3 forward() const { return forward_; }
  // Distance of a world point in front of the eye along forward() (minus the
  // eye-space z).
  double eye_depth(const Vec3& world) const;
  // The plane through p perpendicular to the viewing direction.
  Plane film_plane(const Vec3& p) const { return {p, forward_}; }
  // World length of one pixel at p, measured on the film plane through p;
  // 1 when p does not project or the length is not finite and positive.
  double world_per_pixel(const Vec3& p) const;

  const View& view() const { return view_; }
  // Pixels per inch of the input surface (96 when the view gives none).
  double dpi() const { return view_.dpi > 0 ? view_.dpi : 96.0; }

 private:
  View view_;
  Mat4 pv_, inv_;
  Vec3 right_, up_, forward_;
};

}  // namespace sketchlab
