#include "anchor_binding.hpp"

#include <algorithm>
#include <cmath>

#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/geometry/split.hpp"

namespace sketchlab::cassie {

Binding bind_to_anchors(const Curve& fitted, const std::vector<Candidate>& cands, double reuse) {
  Binding b;
  b.curve = fitted;
  b.anchor.assign(cands.size(), -1);
  std::vector<double> dist(cands.size(), 0.0);
  double t_min = 0.0;  // earlier anchors stay before later constraints
  for (std::size_t i = 0; i < cands.size(); ++i) {
    const ClosestPoint cp = closest_point(b.curve, cands[i].target);
    dist[i] = cp.distance;
    const double t = std::clamp(cp.t, t_min, b.curve.t_max());
    const Vec3 p = evaluate(b.curve, t);
    const int k = std::min(static_cast<int>(std::floor(t)), b.curve.segment_count() - 1);
    const double d0 = (p - b.curve.control_points[3 * k]).norm();
    const double d1 = (p - b.curve.control_points[3 * k + 3]).norm();
    int joint;
    if (std::min(d0, d1) <= reuse) {
      joint = d0 <= d1 ? k : k + 1;
    } else {
      auto [split, j] = insert_joint(b.curve, t);
      // Joints after the new one shift by one; only earlier ones are bound.
      b.curve = std::move(split);
      joint = j;
    }
    t_min = joint;
    const int index = 3 * joint;
    for (std::size_t o = 0; o < i; ++o) {
      if (b.anchor[o] != index) continue;
      if (dist[o] <= dist[i]) {
        b.anchor[i] = -2;  // lost the clash
      } else {
        b.anchor[o] = -1;
      }
    }
    if (b.anchor[i] != -2) b.anchor[i] = index;
    else b.anchor[i] = -1;
  }
  return b;
}

}  // namespace sketchlab::cassie
