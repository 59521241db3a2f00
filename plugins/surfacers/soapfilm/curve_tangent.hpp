#pragma once
// One-sided curve tangents: at a sharp joint the tangent leaving forward
// (increasing t) differs from the one arriving (the kernel's tangent() takes
// the segment starting at the joint).
#include "sketchlab/curve.hpp"

namespace sketchlab::soapfilm {

// Unit tangent (direction of increasing t) at t, taken on the cubic piece
// after t (`after` = true) or before it. Falls back to the nearest distinct
// control point when the derivative vanishes.
Vec3 one_sided_tangent(const Curve& curve, double t, bool after);

}  // namespace sketchlab::soapfilm
