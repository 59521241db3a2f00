#include "multi_view.hpp"

#include "sketchlab/geometry/split.hpp"

namespace sketchlab::synthetic {

std::vector<PlannedStroke> justdrawit_strokes(const GroundTruthNetwork& plan) {
  std::vector<PlannedStroke> out;
  for (std::size_t i = 0; i < plan.curves.size(); ++i) {
    const GroundTruthCurve& gc = plan.curves[i];
    if (gc.curve.closed) {
      out.push_back({gc.curve, gc.layer, i, 0});
      continue;
    }
    const double t = gc.curve.t_max();
    out.push_back({sub_curve(gc.curve, 0.0, 0.6 * t), gc.layer, i, 0});
    out.push_back({sub_curve(gc.curve, 0.45 * t, t), gc.layer, i, 0});
  }
  for (std::size_t i = 0; i < plan.curves.size(); ++i) out.push_back({plan.curves[i].curve, plan.curves[i].layer, i, 1});
  return out;
}

}  // namespace sketchlab::synthetic
