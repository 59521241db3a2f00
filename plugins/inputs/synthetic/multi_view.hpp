#pragma once
// JustDrawIt-style drawing (Grimm & Joshi 2012): "a single curve can be
// created in a variety of ways, from one long stroke to multiple, disjoint
// strokes" (§1, Figure 2), and a curve is given its depth by changing the
// view and oversketching it (§2, Figure 6: "the user rotates the camera to
// the new view direction, oversketches").
#include <optional>
#include <vector>

#include "ground_truth.hpp"
#include "planned_stroke.hpp"

namespace sketchlab::synthetic {

// The plan's curves drawn JustDrawIt-style: first, in view 0, every open
// curve as two strokes — [0, 0.6] and then [0.45, 1] of its parameter range,
// the second starting back on the first (a multi-stroke curve, Fig. 2) — and
// every closed curve as one; then, in view 1, every curve oversketched once
// (Fig. 6): an open curve over [0.1, 0.9] of its range (§4.2: an oversketch's
// ends merge with the curve without overhang), a closed one whole. Every stroke's `intended` is its curve. With `eye` (the
// first view's eye), every stroke of a curve carries the draw plane the
// person placed for it (`placed_draw_plane`); without, none.
std::vector<PlannedStroke> justdrawit_strokes(const GroundTruthNetwork& plan,
                                              const std::optional<Vec3>& eye = std::nullopt);

// The draw plane a JustDrawIt user places to draw `curve` (§5.1: "the user
// can place a draw plane" from existing curves, at a curve point with its
// tangent, normal or binormal, or through two points; the stroke is then cast
// onto it): a planar curve's own plane; for a line, the plane containing it
// that faces `eye` best. Placed exactly, as snapping it to drawn curve points
// allows (a choice: the pen's error is the only error). Throws
// std::invalid_argument for a curve that is not planar.
Vec4 placed_draw_plane(const Curve& curve, const Vec3& eye);

}  // namespace sketchlab::synthetic
