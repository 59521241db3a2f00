#include "surface_quality.hpp"

#include <algorithm>
#include <numeric>

namespace sketchlab::hermite_rbf {

SurfaceQuality surface_quality(const Mesh& mesh, const PointTree& curves, double margin) {
  SurfaceQuality q;
  Box3 region;
  for (const Vec3& p : curves.points()) region.extend(p);
  region.min() -= Vec3::Constant(margin);
  region.max() += Vec3::Constant(margin);
  std::vector<double> vertex_area(mesh.vertices.size(), 0.0);
  for (const auto& f : mesh.faces) {
    const Vec3 &a = mesh.vertices[static_cast<std::size_t>(f[0])], &b = mesh.vertices[static_cast<std::size_t>(f[1])],
               &c = mesh.vertices[static_cast<std::size_t>(f[2])];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    q.area += area;
    for (int v : f) vertex_area[static_cast<std::size_t>(v)] += area / 3.0;
    if (!region.contains((a + b + c) / 3.0)) q.outside_area += area;
  }
  if (!(q.area > 0.0)) return q;
  q.outside_fraction = q.outside_area / q.area;
  std::vector<std::pair<double, double>> distance_area;  // (distance, area)
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!(vertex_area[v] > 0.0)) continue;
    const double d = curves.nearest(mesh.vertices[v]).second;
    distance_area.emplace_back(d, vertex_area[v]);
    q.distance_mean += d * vertex_area[v];
    q.distance_max = std::max(q.distance_max, d);
  }
  q.distance_mean /= q.area;
  std::sort(distance_area.begin(), distance_area.end());
  double below = 0.0;
  for (const auto& [d, a] : distance_area) {
    below += a;
    q.distance_p95 = d;
    if (below >= 0.95 * q.area) break;
  }
  return q;
}

}  // namespace sketchlab::hermite_rbf
