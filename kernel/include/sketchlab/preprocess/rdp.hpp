#pragma once
// Ramer–Douglas–Peucker polyline simplification (Ramer 1972, Douglas &
// Peucker 1973), used by CASSIE (thesis §3.2.2) before Bézier fitting.
#include <cstddef>
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab {

// Indices (increasing, first 0 and last n-1) of the points kept by RDP with
// tolerance epsilon >= 0 (units of the points): every dropped point lies
// within epsilon of the segment joining the kept points around it. An empty
// input gives an empty result, one point gives {0}. Throws
// std::invalid_argument for a negative or non-finite epsilon.
std::vector<std::size_t> rdp_indices(const std::vector<Vec3>& points, double epsilon);

// The kept points themselves.
std::vector<Vec3> rdp_simplify(const std::vector<Vec3>& points, double epsilon);

}  // namespace sketchlab
