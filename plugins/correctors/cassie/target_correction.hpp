#pragma once
// What happens to the detected constraints once the stroke is fitted: their
// targets are corrected towards the new curve (item 8), placed on it, and
// weighted (item 11).
#include <vector>

#include "cassie_params.hpp"
#include "constraint_types.hpp"
#include "sketchlab/sketch.hpp"

namespace sketchlab::cassie {

// Item 8 (`Beautifier.CorrectIntersections`): a curve target not at an end
// of its curve is replaced by the nearest to `fitted` of `points` points of
// the old curve within ±`span` metres of arclength of it (evenly spaced,
// the two extremes included). Other kinds are left as they are. With
// `keep_detected` the detected target is tried too (a second reading of
// item 8's "6 points ... tried": off by default, README).
void correct_targets(std::vector<Candidate>& constraints, const Curve& fitted, const Network& network,
                     double span, int points, bool keep_detected = false);

// Sets t_stroke (closest parameter on `curve`) and distance of each
// constraint.
void place_on_stroke(std::vector<Candidate>& constraints, const Curve& curve);

// Item 11 (`ConstraintSolver`): node 2, curve 1.5, grid and plane 1; at least
// weight_endpoint when the constraint's point on the stroke is within δ of a
// stroke end; + tangent_bonus, and a tangent target for E_tangent, when the
// tangents align: for a curve |cos| > cos θ (at a node the parametric
// tangents must point opposite ways, or the same way with
// node_alignment = same), for the plane the stroke tangent within θ of its
// normal. Needs place_on_stroke first.
void assign_weights(std::vector<Candidate>& constraints, const Curve& curve, const Network& network,
                    const Workspace& workspace, const CassieParams& params, const Thresholds& th);

}  // namespace sketchlab::cassie
