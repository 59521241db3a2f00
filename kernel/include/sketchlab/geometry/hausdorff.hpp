#pragma once
// Two-sided (Hausdorff) distance between a curve and a polyline, e.g. a
// fitted or corrected curve and the stroke samples it came from.
#include <algorithm>
#include <vector>

#include "sketchlab/curve.hpp"

namespace sketchlab {

struct HausdorffDistance {
  double curve_to_polyline = 0.0;  // m: farthest curve point from the polyline
  double polyline_to_curve = 0.0;  // m: farthest polyline vertex from the curve
  double max() const { return std::max(curve_to_polyline, polyline_to_curve); }
};

// The curve is sampled `per_segment` + 1 times per Bézier (or line) segment,
// uniformly in parameter (>= 1), and each sample measured against the
// polyline; each polyline vertex is measured against the curve exactly
// (closest_point). Throws std::invalid_argument for an empty polyline or
// per_segment < 1.
HausdorffDistance hausdorff_distance(const Curve& curve, const std::vector<Vec3>& polyline,
                                     int per_segment = 32);

}  // namespace sketchlab
