#pragma once
// Conversions between JustDrawIt point lists and kernel curves, and edit
// helpers. JustDrawIt keeps curves as point lists (§4 "Representation");
// the kernel stores them as poly-Béziers whose segments are straight (inner
// control points at 1/3 and 2/3 of each chord), so point i is at t = i and
// nothing is fitted away. (The edit between two networks is the kernel's
// edit_between, sketchlab/network_diff.hpp.)
#include "point_list.hpp"
#include "sketchlab/edit.hpp"
#include "sketchlab/network.hpp"

namespace sketchlab::justdrawit {

// The curve's points: the joints of a straight-segment curve as they are,
// other curves sampled `spacing` apart (closed curves repeat the first point).
Points3 curve_points(const Curve& curve, double spacing);

// A straight-segment poly-Bézier through the points (>= 2 distinct points;
// closed: the last point is set equal to the first). Throws
// std::invalid_argument on fewer than 2 distinct points.
Curve polyline_curve(const Points3& pts, bool closed);

}  // namespace sketchlab::justdrawit
