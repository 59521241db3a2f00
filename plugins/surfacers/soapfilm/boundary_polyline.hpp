#pragma once
// Sampling a patch boundary (oriented segments) into the closed polygon the
// mesher fills. Every point is evaluated on its curve, so the mesh border
// lies on the boundary curves.
#include <vector>

#include "sketchlab/network.hpp"

namespace sketchlab::soapfilm {

struct BoundaryPolyline {
  std::vector<Vec3> points;   // closed polygon, first point not repeated
  double spacing = 0.0;       // longest arc between consecutive points (m)
};

// `spacing`: wanted distance between samples (m); raised so that at most
// max(`max_points`, pieces) points are used. Throws std::invalid_argument if a piece
// references a missing curve or the boundary has no length.
BoundaryPolyline boundary_polyline(const Network& network, const std::vector<OrientedSegment>& boundary,
                                   double spacing, int max_points);

// Curve parameters along one boundary piece from t_from to t_to, n >= 2 of
// them (on a closed curve the piece may wrap across the seam; it is read the
// way that is a union of the network's segments).
std::vector<double> piece_parameters(const Network& network, const OrientedSegment& piece, int n);

}  // namespace sketchlab::soapfilm
