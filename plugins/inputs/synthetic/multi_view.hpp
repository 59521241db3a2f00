#pragma once
// JustDrawIt-style drawing (Grimm & Joshi 2012): "a single curve can be
// created in a variety of ways, from one long stroke to multiple, disjoint
// strokes" (§1, Figure 2), and a curve is given its depth by changing the
// view and oversketching it (§2, Figure 6: "the user rotates the camera to
// the new view direction, oversketches").
#include <vector>

#include "ground_truth.hpp"
#include "planned_stroke.hpp"

namespace sketchlab::synthetic {

// The plan's curves drawn JustDrawIt-style: first, in view 0, every open
// curve as two strokes — [0, 0.6] and then [0.45, 1] of its parameter range,
// the second starting back on the first (a multi-stroke curve, Fig. 2) — and
// every closed curve as one; then, in view 1, every curve oversketched once
// whole (Fig. 6). Every stroke's `intended` is its curve.
std::vector<PlannedStroke> justdrawit_strokes(const GroundTruthNetwork& plan);

}  // namespace sketchlab::synthetic
