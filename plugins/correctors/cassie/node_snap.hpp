#pragma once
// Item 8's node snap (CASSIE app, `FinalStroke.GetConstraint`), which the app
// applies wherever it makes a constraint on an old curve: at the brush's
// detection (item 6) and again at the target item 8's correction moved.
#include "cassie_params.hpp"
#include "constraint_types.hpp"
#include "sketchlab/network.hpp"

namespace sketchlab::cassie {

// A curve-kind candidate (`c.curve`, `c.t_curve`, `c.target` on it) becomes
// node kind, at the node's position and parameter, when an end node of the
// crossed piece of the curve (the nearest nodes on it before and after
// t_curve) is within th.node_snap of the target and has more than one
// incidence, or when the curve's own end node, of one incidence, is within
// th.dangling_snap (item 22: an intersection reuses a node within δ on the
// old curve). The nearer of the two piece ends wins. Other kinds, and curve
// candidates with no such node, are left as they are.
void snap_to_node(Candidate& c, const Network& net, const Thresholds& th);

}  // namespace sketchlab::cassie
