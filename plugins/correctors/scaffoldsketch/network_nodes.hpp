#pragma once
// Nodes (intersections) for a corrected curve, so that surfacers and metrics
// see where it meets the existing network.
#include "sketchlab/edit.hpp"
#include "sketchlab/network.hpp"

namespace sketchlab::scaffoldsketch {

// Records in `edit` that the new curve `curve` passes through p at parameter
// t, together with every existing curve within `tolerance` (m) of p (at its
// closest parameter). Joins a node of the edit or of the network within
// `tolerance` (nodes_replaced with the added incidences) or adds a node with
// id next_node++. Does nothing when no other curve passes there. Incidences
// are kept sorted by (curve, t); an incidence already present is not repeated.
void connect_point(const Network& network, const Vec3& p, CurveId curve, double t,
                   double tolerance, Edit& edit, NodeId& next_node);

}  // namespace sketchlab::scaffoldsketch
