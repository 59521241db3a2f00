#pragma once
// Binding constraints to control points (CASSIE app, item 12,
// `BezierCurve.SplitForConstraints`; thesis eq. 3.3–3.4).
#include <vector>

#include "constraint_types.hpp"

namespace sketchlab::cassie {

struct Binding {
  Curve curve;              // the fitted curve split once for all constraints
  std::vector<int> anchor;  // per constraint: its control point (3·joint), or -1 when dropped
};

// Constraints, in order along the stroke (t_stroke ascending), are bound
// one after the other to the current, already split curve: a constraint
// whose closest point lies within `reuse` of either anchor (joint) of its
// Bézier reuses the nearer one, otherwise the curve is split there (de
// Casteljau) and the new joint is its anchor. When two constraints land on
// one anchor, the one whose target is closer to the curve keeps it and the
// other is dropped (anchor -1), not made an infeasible subset.
Binding bind_to_anchors(const Curve& fitted, const std::vector<Candidate>& constraints, double reuse);

}  // namespace sketchlab::cassie
