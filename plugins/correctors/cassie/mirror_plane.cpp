#include "mirror_plane.hpp"

#include <algorithm>
#include <cmath>

#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab::cassie {

bool project_onto_mirror(Curve& curve, const Workspace& ws, const std::vector<Vec3>& intersections,
                         double max_distance, double on_plane, double angle) {
  if (!ws.mirror_enabled || !(ws.mirror_normal.norm() > 0)) return false;
  const Vec3 n = ws.mirror_normal.normalized();
  const double off = ws.mirror_offset / ws.mirror_normal.norm();
  auto side = [&](const Vec3& p) { return n.dot(p) - off; };
  const auto& cp = curve.control_points;
  double d = 0.0;
  if (curve.kind == CurveKind::line) {
    d = 0.25 * (std::abs(side(cp.front())) + std::abs(side(cp.back())));
  } else {
    for (const Vec3& p : cp) d = std::max(d, std::abs(side(p)));
  }
  if (!(d < max_distance)) return false;
  for (const Vec3& q : intersections)
    if (std::abs(side(q)) > on_plane) return false;
  const double c = std::cos(angle);
  if (std::abs(tangent(curve, 0.0).dot(n)) >= c || std::abs(tangent(curve, curve.t_max()).dot(n)) >= c)
    return false;
  for (Vec3& p : curve.control_points) p -= side(p) * n;
  return true;
}

}  // namespace sketchlab::cassie
