#include "network_curves.hpp"

#include <stdexcept>

#include "sketchlab/geometry/arclength.hpp"

namespace sketchlab::justdrawit {

Points3 curve_points(const Curve& curve, double spacing) {
  const auto& cp = curve.control_points;
  const int k = curve.segment_count();
  if (k == 0) return Points3(cp.begin(), cp.end());
  bool straight = true;
  for (int s = 0; s < k && straight; ++s) {
    const Vec3 &a = cp[3 * s], &b = cp[3 * s + 3];
    const double tol = 1e-9 * std::max(1.0, (b - a).norm());
    straight = (cp[3 * s + 1] - (a + (b - a) / 3.0)).norm() <= tol &&
               (cp[3 * s + 2] - (a + 2.0 * (b - a) / 3.0)).norm() <= tol;
  }
  if (straight) {
    Points3 out;
    out.reserve(k + 1);
    for (int s = 0; s <= k; ++s) out.push_back(cp[3 * s]);
    return out;
  }
  return sample_with_spacing(curve, spacing);
}

Curve polyline_curve(const Points3& input, bool closed) {
  Points3 pts = dedupe(input, 1e-12);
  if (closed && pts.size() > 2 && (pts.back() - pts.front()).norm() <= 1e-12) pts.pop_back();
  if (pts.size() < 2) throw std::invalid_argument("justdrawit: a curve needs two distinct points");
  if (closed && pts.size() >= 3) pts.push_back(pts.front());
  Curve c;
  c.kind = CurveKind::bezier;
  c.closed = closed && pts.size() >= 4;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const Vec3 e = pts[i + 1] - pts[i];
    c.control_points.push_back(pts[i]);
    c.control_points.push_back(pts[i] + e / 3.0);
    c.control_points.push_back(pts[i] + 2.0 * e / 3.0);
  }
  c.control_points.push_back(pts.back());
  c.sharp.assign(pts.size(), false);
  return c;
}

}  // namespace sketchlab::justdrawit
