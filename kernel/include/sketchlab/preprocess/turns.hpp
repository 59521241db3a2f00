#pragma once
// Direction turns along a polyline, as the CASSIE app measures them for hooks
// and corners (reference items 3–4, `InputStroke.GetG1sections`): the
// direction at a sample is the average of its two adjacent edges (the chord
// p[i+1] − p[i−1], one-sided at the ends). Two readings of "the direction
// turns at sample i" are kept (see `TurnSpan`).
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab {

enum class TurnSpan {
  // Between the directions at i−1 and i: how much the averaged direction
  // turns from one sample to the next (item 3's hooks).
  consecutive,
  // Between the directions at i−1 and i+1, i.e. across the sample (item 4's
  // corners).
  across,
};

// Turn (radians, [0, π]) at each point; 0 at the two ends and where a
// direction is undefined (coincident points). Empty input gives empty output.
std::vector<double> sample_turns(const std::vector<Vec3>& points, TurnSpan span);

}  // namespace sketchlab
