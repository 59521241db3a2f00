#pragma once
#include <utility>

#include "sketchlab/curve.hpp"

namespace sketchlab {

// De Casteljau split at global parameter t in (0, t_max). The left curve
// covers [0, t], the right [t, t_max]; their union traces the same points.
// Sharp flags are kept; the cut joint is smooth on both sides. Kind is kept.
std::pair<Curve, Curve> split(const Curve& curve, double t);

// Inserts a joint at t (de Casteljau inside one segment) without changing the
// shape; returns the new curve and the new joint index (t maps to an integer).
// If t is already a joint (within 1e-12) the curve is returned unchanged.
std::pair<Curve, int> insert_joint(const Curve& curve, double t);

// The part of the curve between t0 < t1, as a curve with parameter [0, K'].
Curve sub_curve(const Curve& curve, double t0, double t1);

}  // namespace sketchlab
