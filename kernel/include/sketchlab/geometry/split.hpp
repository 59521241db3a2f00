#pragma once
#include <utility>

#include "sketchlab/curve.hpp"

namespace sketchlab {

// De Casteljau split at global parameter t in (0, t_max). The left curve
// covers [0, t], the right [t, t_max]; their union traces the same points.
// Sharp flags are kept; a cut inside a segment is smooth on both sides, a cut
// at an existing joint keeps that joint's flag. Kind is kept; both halves are
// open. Throws std::invalid_argument for t outside (0, t_max) (1e-12 margin).
std::pair<Curve, Curve> split(const Curve& curve, double t);

// Inserts a joint at t (de Casteljau inside one segment) without changing the
// shape; returns the new curve and the new joint index (t maps to an integer).
// If t is already a joint (within 1e-12) the curve is returned unchanged.
std::pair<Curve, int> insert_joint(const Curve& curve, double t);

// The part of the curve between t0 < t1, as a curve with parameter [0, K'].
// t0, t1 are clamped to [0, t_max]; throws std::invalid_argument if they do
// not span more than 1e-12 after clamping.
Curve sub_curve(const Curve& curve, double t0, double t1);

}  // namespace sketchlab
