#pragma once
// The two cuts the CASSIE app makes at a stroke's ends: before solving, an
// end that runs along the curve it meets (item 9); after solving, a short
// dangling piece beyond the last intersection (item 16).
#include <vector>

#include "constraint_types.hpp"
#include "sketchlab/network.hpp"

namespace sketchlab::cassie {

// Item 9: when the first (last) constraint along the stroke is an
// intersection whose target is within `reach` of the stroke's start (end)
// and whose curve's tangent is within `angle` of the stroke's there (as
// lines), the stroke is cut at that constraint's parameter; constraints on
// the removed piece are dropped. `cands` must be placed (place_on_stroke)
// and sorted by t_stroke; their t_stroke refer to the returned curve.
Curve cut_overlaps(const Curve& fitted, std::vector<Candidate>& cands, const Network& network,
                   double reach, double angle);

// Item 16 (`DrawController.TrimDanglingEndpoints`): `joints` are the joint
// indices (control point index / 3) of the enforced intersection and plane
// constraints. The piece before the first (after the last) is removed when
// it is shorter than `fraction` of the curve's length and than `length`.
// Returns the number of segments removed at the start (joint indices shift
// by it); a closed curve is left as it is.
int trim_dangling(Curve& curve, const std::vector<int>& joints, double fraction, double length);

}  // namespace sketchlab::cassie
