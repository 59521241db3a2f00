#pragma once
// Where a 2D line crosses the projection of a 3D curve (Schmidt et al. 2009
// §3.1, Figure 7c "intersections with lines/curves"): the 3D point of the
// curve at the crossing is a position constraint C° for a stroke endpoint.
#include <vector>

#include "sketchlab/camera.hpp"
#include "sketchlab/curve.hpp"

namespace sketchlab::analytic {

struct CurveCrossing {
  double t = 0.0;           // global curve parameter
  Vec3 point = Vec3::Zero();  // evaluate(curve, t): on the curve by construction
  Vec2 pixel = Vec2::Zero();  // its projection (on the line up to ~1e-9 px)
};

// Crossings of the infinite image line through pixels a and b with the
// projected curve whose pixel lies within `radius` pixels of `near`, ordered
// by curve parameter. Sign changes of the signed pixel distance to the line
// are found on `samples_per_segment` samples per Bézier segment and refined
// by bisection on t, so each point lies exactly on the 3D curve. Intervals
// with a sample on or behind the eye are skipped. Empty for a degenerate line
// (|b − a| < 1e-9 px) or a malformed curve. A line that only touches the
// projection (no sign change) has no crossing.
std::vector<CurveCrossing> curve_line_crossings(const Curve& curve, const Camera& camera, const Vec2& a,
                                                const Vec2& b, const Vec2& near, double radius,
                                                int samples_per_segment = 32);

}  // namespace sketchlab::analytic
