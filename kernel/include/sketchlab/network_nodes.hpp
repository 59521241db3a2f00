#pragma once
// Nodes (intersections) for a corrected curve, so that surfacers and metrics
// see where it meets the existing network. Shared by the correctors that
// place curve points exactly on existing curves (ScaffoldSketch, analytic).
#include <functional>

#include "sketchlab/edit.hpp"
#include "sketchlab/network.hpp"

namespace sketchlab {

// Records in `edit` that the new curve `curve` passes through p at parameter
// t, together with every existing curve within `tolerance` (m) of p (at its
// closest parameter). Joins a node of the edit or of the network within
// `tolerance` (nodes_replaced with the added incidences) or adds a node with
// id next_node++. Does nothing when no other curve passes there. Incidences
// are kept sorted by (curve, t); an incidence already present is not repeated.
// Curves for which `ignore` (when given) returns true are not connected, e.g.
// construction guidelines that are not part of the curve network.
void connect_point(const Network& network, const Vec3& p, CurveId curve, double t,
                   double tolerance, Edit& edit, NodeId& next_node,
                   const std::function<bool(CurveId)>& ignore = {});

}  // namespace sketchlab
