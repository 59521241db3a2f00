#include "sketchlab/draw_plane.hpp"

#include <cmath>
#include <stdexcept>

namespace sketchlab {

Vec4 plane_through(const Vec3& point, const Vec3& normal) {
  const double len = normal.norm();
  if (!point.allFinite() || !normal.allFinite() || !(len > 0.0))
    throw std::invalid_argument("plane_through: the point and normal must be finite, normal non-zero");
  const Vec3 n = normal / len;
  Vec4 p;
  p << n, n.dot(point);
  return p;
}

bool pixel_on_plane(const View& view, const Vec4& plane, const Vec2& pixel, Vec3& world) {
  const Ray ray = pixel_to_ray(view, pixel);
  const Vec3 n = plane.head<3>();
  const double denom = n.dot(ray.direction);
  // Grazing rays put the point absurdly far away; refuse them like misses.
  if (!(std::abs(denom) > 1e-9)) return false;
  const double s = (plane[3] - n.dot(ray.origin)) / denom;
  if (!(s >= 0.0) || !std::isfinite(s)) return false;
  world = ray.origin + s * ray.direction;
  return world.allFinite();
}

Stroke lift_to_draw_plane(const Stroke& stroke, std::string& error) {
  if (!stroke.is_2d() || !stroke.draw_plane) return stroke;
  Stroke lifted = stroke;
  lifted.samples_are_pixels = false;
  for (std::size_t i = 0; i < lifted.samples.size(); ++i) {
    Sample& s = lifted.samples[i];
    Vec3 world;
    if (!pixel_on_plane(*stroke.view, *stroke.draw_plane, s.position.head<2>(), world)) {
      error = "stroke " + std::to_string(stroke.id) + " sample " + std::to_string(i) +
              ": its ray misses the draw plane";
      return stroke;
    }
    s.position = world;
  }
  return lifted;
}

}  // namespace sketchlab
