#pragma once
#include "sketchlab/curve.hpp"

namespace sketchlab {

// Tight axis-aligned bounding box (extrema from the roots of the derivative).
Box3 bounding_box(const Curve& curve);

// Bounding box of the curve between parameters t0 <= t1.
Box3 bounding_box(const Curve& curve, double t0, double t1);

}  // namespace sketchlab
