#pragma once
// Evaluation of cubic poly-Bézier curves (see curve.hpp for the layout).
// Global parameter t in [0, K]; values outside are clamped. At an interior
// joint t = k the right segment (k) is used, except t = K uses segment K-1.
#include <array>

#include "sketchlab/curve.hpp"

namespace sketchlab {

// Segment index and local parameter u in [0,1] for a global t.
std::pair<int, double> locate(const Curve& curve, double t);

// The 4 control points of segment k.
std::array<Vec3, 4> segment_points(const Curve& curve, int k);

Vec3 evaluate(const Curve& curve, double t);
// d/dt and d²/dt² with respect to the global parameter.
Vec3 derivative(const Curve& curve, double t);
Vec3 second_derivative(const Curve& curve, double t);
// Unit tangent (falls back to the chord direction where the derivative
// vanishes, e.g. coincident control points).
Vec3 tangent(const Curve& curve, double t);

// Single cubic segment helpers (u in [0,1]).
// De Casteljau subdivision at u: the control points of [0, u] and [u, 1]
// (their shared end is the point at u, exact at u = 0 and u = 1).
std::pair<std::array<Vec3, 4>, std::array<Vec3, 4>> bezier_subdivide(const std::array<Vec3, 4>& p, double u);
// The point at u (de Casteljau: the shared end of bezier_subdivide).
Vec3 bezier_point(const std::array<Vec3, 4>& p, double u);
Vec3 bezier_derivative(const std::array<Vec3, 4>& p, double u);

}  // namespace sketchlab
