#pragma once
// A View with its matrices precomputed, for the many projections and rays the
// inference needs. Pixels are the View's window coordinates.
#include <optional>

#include "sketchlab/view.hpp"

namespace sketchlab::analytic {

class Camera {
 public:
  // Throws std::invalid_argument when the view is singular (see view.hpp).
  explicit Camera(const View& view);

  // Pixel of a world point; nullopt when the point is on or behind the eye.
  std::optional<Vec2> project(const Vec3& world) const;
  // Ray through a pixel (origin on the near plane, unit direction).
  Ray ray(const Vec2& pixel) const;
  // Pixel the direction d converges to (its vanishing point); nullopt when d is
  // parallel to the image plane (vanishing point at infinity).
  std::optional<Vec2> vanishing_point(const Vec3& d) const;
  // Image-plane axes in world space (right, up) and the viewing direction.
  Vec3 right() const { return right_; }
  Vec3 up() const { return up_; }
  Vec3 forward() const { return forward_; }
  const View& view() const { return view_; }
  double dpi() const { return view_.dpi > 0 ? view_.dpi : 96.0; }

 private:
  View view_;
  Mat4 pv_, inv_;
  Vec3 right_, up_, forward_;
};

}  // namespace sketchlab::analytic
