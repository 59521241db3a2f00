#pragma once
// Polylines: ordered point lists (n x 3), metres or pixels.
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab {

double polyline_length(const std::vector<Vec3>& points);
// Cumulative arclength at each point (first 0).
std::vector<double> cumulative_length(const std::vector<Vec3>& points);
// n >= 2 points equally spaced along the polyline.
std::vector<Vec3> resample_polyline(const std::vector<Vec3>& points, int n);
// Point at arclength s along the polyline (clamped).
Vec3 point_at_length(const std::vector<Vec3>& points, double s);

}  // namespace sketchlab
