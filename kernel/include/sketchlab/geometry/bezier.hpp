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
Vec3 bezier_point(const std::array<Vec3, 4>& p, double u);
Vec3 bezier_derivative(const std::array<Vec3, 4>& p, double u);

}  // namespace sketchlab
