#pragma once
// Small sketches with known geometry, and the pinhole projection the
// renderer must reproduce (computed here without VTK).
#include <cmath>
#include <numbers>

#include "sketchlab/network_curve.hpp"
#include "sketchlab/sketch.hpp"
#include "sketchlab/viewer/camera.hpp"
#include "sketchlab/viewer/png_image.hpp"

namespace sketchlab::test {

inline NetworkCurve line_curve(CurveId id, const Vec3& a, const Vec3& b, Layer layer) {
  return make_network_curve(id, make_line(a, b), layer);
}

// One straight shape curve from a to b.
inline Sketch line_sketch(const Vec3& a, const Vec3& b) {
  Sketch sketch;
  Edit edit;
  edit.curves_added.push_back(line_curve(1, a, b, Layer::shape));
  sketch.network.apply(edit);
  return sketch;
}

// The square [-h, h]^2 in the plane z = 0: four shape curves, corner nodes,
// and (when `patch`) a two-triangle patch filling it.
inline Sketch square_sketch(double h, bool patch) {
  const Vec3 c[4] = {{-h, -h, 0}, {h, -h, 0}, {h, h, 0}, {-h, h, 0}};
  Sketch sketch;
  Edit edit;
  for (int i = 0; i < 4; ++i)
    edit.curves_added.push_back(line_curve(i + 1, c[i], c[(i + 1) % 4], Layer::shape));
  for (int i = 0; i < 4; ++i) {
    Node node;
    node.id = static_cast<NodeId>(i + 1);
    node.position = c[i];
    node.incidences = {{static_cast<CurveId>(i + 1), 0.0},
                       {static_cast<CurveId>((i + 3) % 4 + 1), 1.0}};
    edit.nodes_added.push_back(node);
  }
  if (patch) {
    Patch p;
    p.id = 1;
    for (int i = 0; i < 4; ++i)
      p.boundary.push_back({static_cast<CurveId>(i + 1), 0.0, 1.0, static_cast<NodeId>(i + 1),
                            static_cast<NodeId>((i + 1) % 4 + 1)});
    p.mesh.vertices.assign(c, c + 4);
    p.mesh.faces = {{0, 1, 2}, {0, 2, 3}};
    edit.patches_added.push_back(p);
  }
  sketch.network.apply(edit);
  return sketch;
}

// Pixel (x from the left, y from the TOP row) where `p` projects in a
// viewport of width x height pixels whose left column is x0, for a
// perspective camera with a vertical field of view (VTK's convention).
inline Vec2 project(const viewer::Camera& cam, const Vec3& p, int x0, int width, int height) {
  const Vec3 w = (cam.focal_point - cam.position).normalized();
  const Vec3 r = w.cross(cam.view_up).normalized();
  const Vec3 v = r.cross(w);
  const Vec3 d = p - cam.position;
  const double z = d.dot(w);
  const double f = 1.0 / std::tan(0.5 * cam.view_angle_deg * std::numbers::pi / 180.0);
  const double aspect = static_cast<double>(width) / height;
  const double ndc_x = f / aspect * d.dot(r) / z;
  const double ndc_y = f * d.dot(v) / z;
  return {x0 + 0.5 * (ndc_x + 1.0) * width, height - 0.5 * (ndc_y + 1.0) * height};
}

// Distance in pixels from q to the segment [a, b].
inline double pixel_distance_to_segment(const Vec2& q, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double t = std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (q - (a + t * ab)).norm();
}

inline bool is_dark(const viewer::RgbImage& img, int x, int y, int threshold = 90) {
  const auto* p = img.at(x, y);
  return p[0] < threshold && p[1] < threshold && p[2] < threshold;
}

// Darkest pixel in the (2r+1)^2 neighbourhood of (x, y) is dark.
inline bool dark_near(const viewer::RgbImage& img, double x, double y, int r = 2) {
  const int cx = static_cast<int>(std::floor(x)), cy = static_cast<int>(std::floor(y));
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const int px = cx + dx, py = cy + dy;
      if (px >= 0 && py >= 0 && px < img.width && py < img.height && is_dark(img, px, py))
        return true;
    }
  return false;
}

}  // namespace sketchlab::test
