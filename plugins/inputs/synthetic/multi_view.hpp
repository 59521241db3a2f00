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
// every closed curve as one stroke (closing_loop); then, in view 1, every
// curve oversketched once (Fig. 6): an open curve over [0.1, 0.9] of its
// range (§4.2: an oversketch's ends merge with the curve without overhang),
// a closed one whole from its start. Every stroke's `intended` is its
// curve. With `eye` (the first view's eye), every stroke of a curve carries
// the draw plane the person placed for it (`placed_draw_plane`); without,
// none.
std::vector<PlannedStroke> justdrawit_strokes(const GroundTruthNetwork& plan,
                                              const std::optional<Vec3>& eye = std::nullopt);

// Where the stroke of a closed curve starts (curve parameter) and how far
// past its start it runs (fraction of the loop's parameter range).
inline constexpr double loop_start = 0.5;
inline constexpr double closing_overlap = 0.15;

// The closed curve `loop` traced from parameter t (0 < t < t_max) round to t
// again, as a closed curve with the same points.
Curve loop_from(const Curve& loop, double t);

// A closed curve as a person draws it in one stroke (choices; the paper
// gives no figure): started in a free stretch, midway between its first two
// joints (loop_start; every junction of the built-in models is at a joint),
// once round and on over its start by closing_overlap. Started at a joint,
// the loop starts where another curve ends (the mug's base under a side
// line), and §4.3's rule that a stroke applying to the last edited curve
// goes to it made the loop an extension of that line. Ending exactly on its
// start leaves a join with no gap, which eq. 2 (α_t < 0.3) rejects where
// the seam turns tightly at the scale of d (the lamp shade's 95 px wide top
// ellipse, 6 px radius of curvature at its tips, d = 15 px), so the loop
// stayed open; running on over its start, its end merges with its start
// (§4.3 (1)). Returns an open curve. Throws std::invalid_argument for an
// open `loop`.
Curve closing_loop(const Curve& loop);

// The draw plane a JustDrawIt user places to draw `curve` (§5.1: "the user
// can place a draw plane" from existing curves, at a curve point with its
// tangent, normal or binormal, or through two points; the stroke is then cast
// onto it): a planar curve's own plane; for a line, the plane containing it
// that faces `eye` best. Placed exactly, as snapping it to drawn curve points
// allows (a choice: the pen's error is the only error). Throws
// std::invalid_argument for a curve that is not planar.
Vec4 placed_draw_plane(const Curve& curve, const Vec3& eye);

}  // namespace sketchlab::synthetic
