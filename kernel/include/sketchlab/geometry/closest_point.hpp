#pragma once
#include <vector>

#include "sketchlab/curve.hpp"

namespace sketchlab {

struct ClosestPoint {
  double t = 0.0;      // global curve parameter
  Vec3 point;          // evaluate(curve, t)
  double distance = 0.0;
};

// Closest point of the curve to p. Robust: per segment, a coarse scan seeds
// Newton iterations on (B(u)-p)·B'(u) = 0, guarded by bisection, and segment
// ends are checked, so the result is never farther than the best of a dense
// sampling of the curve (up to 1e-12 m).
ClosestPoint closest_point(const Curve& curve, const Vec3& p);

// Closest point on a polyline (at least one point). t is the fractional index
// (i + u between points i and i+1).
ClosestPoint closest_point_on_polyline(const std::vector<Vec3>& polyline, const Vec3& p);

// Closest pair between a curve and a polyline: t on the curve, point on the
// curve, distance between them.
ClosestPoint closest_point_to_polyline(const Curve& curve, const std::vector<Vec3>& polyline);

}  // namespace sketchlab
