#include "sketchlab/viewer/camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/geometry/bounding_box.hpp"

namespace sketchlab::viewer {
namespace {

void extend(Box3& box, const Vec3& p) {
  if (p.allFinite()) box.extend(p);
}

// The workspace frame: up u, front f (the side a front view looks at), right
// s = u × f.
struct Frame {
  Vec3 up, front, right;
};

Frame workspace_frame(const Vec3& up_in) {
  Vec3 u = up_in.allFinite() && up_in.norm() > 1e-12 ? up_in.normalized() : Vec3::UnitY();
  const Vec3 reference = std::abs(u.z()) > 0.9 ? Vec3(-Vec3::UnitY()) : Vec3(Vec3::UnitZ());
  const Vec3 f = (reference - reference.dot(u) * u).normalized();
  return {u, f, u.cross(f)};
}

}  // namespace

std::string_view to_string(ViewDirection view) {
  switch (view) {
    case ViewDirection::iso: return "iso";
    case ViewDirection::front: return "front";
    case ViewDirection::top: return "top";
    case ViewDirection::side: return "side";
  }
  return "iso";
}

ViewDirection view_direction_from_string(std::string_view name) {
  for (ViewDirection v :
       {ViewDirection::iso, ViewDirection::front, ViewDirection::top, ViewDirection::side})
    if (to_string(v) == name) return v;
  throw std::invalid_argument("view '" + std::string(name) +
                              "' is not one of iso, front, top, side");
}

Box3 scene_bounds(const std::vector<const Sketch*>& sketches) {
  Box3 box;  // empty
  for (const Sketch* sketch : sketches) {
    if (!sketch) continue;
    for (const auto& [id, nc] : sketch->network.curves()) {
      if (nc.curve.segment_count() < 1) continue;
      const Box3 b = bounding_box(nc.curve);
      if (!b.isEmpty() && b.min().allFinite() && b.max().allFinite()) box.extend(b);
    }
    for (const auto& [id, node] : sketch->network.nodes()) extend(box, node.position);
    for (const auto& [id, patch] : sketch->network.patches())
      for (const Vec3& v : patch.mesh.vertices) extend(box, v);
    for (const auto& [id, stroke] : sketch->strokes)
      if (!stroke.samples_are_pixels)
        for (const Sample& s : stroke.samples) extend(box, s.position);
  }
  return box;
}

std::vector<Vec3> scene_points(const std::vector<const Sketch*>& sketches, double spacing) {
  if (!std::isfinite(spacing) || spacing <= 0.0)
    throw std::invalid_argument("scene_points: spacing must be a positive number");
  std::vector<Vec3> out;
  const auto add = [&out](const Vec3& p) {
    if (p.allFinite()) out.push_back(p);
  };
  for (const Sketch* sketch : sketches) {
    if (!sketch) continue;
    for (const auto& [id, nc] : sketch->network.curves())
      if (nc.curve.segment_count() >= 1 && validate(nc.curve).empty())
        for (const Vec3& p : sample_with_spacing(nc.curve, spacing)) add(p);
    for (const auto& [id, node] : sketch->network.nodes()) add(node.position);
    for (const auto& [id, patch] : sketch->network.patches())
      for (const Vec3& v : patch.mesh.vertices) add(v);
    for (const auto& [id, stroke] : sketch->strokes)
      if (!stroke.samples_are_pixels)
        for (const Sample& s : stroke.samples) add(s.position);
  }
  return out;
}

Camera fit_camera(const std::vector<const Sketch*>& sketches, ViewDirection view, double aspect,
                  double margin, double view_angle_deg) {
  if (!std::isfinite(aspect) || aspect <= 0.0)
    throw std::invalid_argument("fit_camera: aspect must be a positive number");
  if (!std::isfinite(view_angle_deg) || view_angle_deg <= 1.0 || view_angle_deg >= 170.0)
    throw std::invalid_argument("fit_camera: view_angle_deg must be in (1, 170)");
  if (!std::isfinite(margin) || margin < 0.0)
    throw std::invalid_argument("fit_camera: margin must be >= 0");

  const Sketch* first = nullptr;
  for (const Sketch* s : sketches)
    if (s && !first) first = s;
  const Frame frame = workspace_frame(first ? first->workspace.up : Vec3::UnitY());

  Box3 box = scene_bounds(sketches);
  const bool empty = box.isEmpty();
  if (empty) box = Box3(Vec3(-0.5, -0.5, -0.5), Vec3(0.5, 0.5, 0.5));
  // A flat or point-like scene still needs a finite frame.
  const double extent = std::max(box.diagonal().norm(), 1e-3);
  const Vec3 centre = box.center();

  Vec3 towards_camera = frame.front, up = frame.up;
  switch (view) {
    case ViewDirection::front: break;
    case ViewDirection::side: towards_camera = frame.right; up = frame.up; break;
    case ViewDirection::top: towards_camera = frame.up; up = -frame.front; break;
    case ViewDirection::iso:
      towards_camera = (frame.front + frame.right + frame.up).normalized();
      up = (frame.up - frame.up.dot(towards_camera) * towards_camera).normalized();
      break;
  }
  const Vec3 right = (-towards_camera).cross(up).normalized();

  // Frame what is drawn, not its bounding box (whose corners stick out far
  // beyond the content in oblique views).
  std::vector<Vec3> points;
  if (empty) {
    for (int c = 0; c < 8; ++c) points.push_back(box.corner(static_cast<Box3::CornerType>(c)));
  } else {
    points = scene_points(sketches, extent / 200.0);
  }

  // Smallest distance d from the centre such that every point projects
  // inside the viewport: for a point at (x right, y up, z towards the camera)
  // relative to the centre, |x| <= (d - z) tan(h/2) and |y| <= (d - z) tan(v/2).
  const double half_v = 0.5 * view_angle_deg * std::numbers::pi / 180.0;
  const double tan_v = std::tan(half_v);
  const double tan_h = tan_v * aspect;
  const double grow = 1.0 + margin;
  double distance = 0.0;
  double nearest = 0.0;  // largest z: the point closest to the camera
  for (const Vec3& p : points) {
    const Vec3 d = p - centre;
    const double x = std::abs(d.dot(right)) * grow;
    const double y = std::abs(d.dot(up)) * grow;
    const double z = d.dot(towards_camera);
    nearest = std::max(nearest, z);
    distance = std::max({distance, z + x / tan_h, z + y / tan_v});
  }
  // Keep every point in front of the camera.
  distance = std::max(distance, nearest + 1e-3 * extent);

  Camera camera;
  camera.focal_point = centre;
  camera.position = centre + distance * towards_camera;
  camera.view_up = up;
  camera.view_angle_deg = view_angle_deg;
  return camera;
}

}  // namespace sketchlab::viewer
