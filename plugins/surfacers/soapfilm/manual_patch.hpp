#pragma once
// User-guided patches (CHI'21 §5.1, thesis §3.3.3): from the segment closest
// to a point, walk the graph always taking the segment whose closest point
// is nearest to that point, until back at the start node. Segments that
// already bound two patches are allowed (non-manifold on purpose).
#include <optional>
#include <vector>

#include "sketchlab/network.hpp"

namespace sketchlab::soapfilm {

struct ManualPatchParams {
  int max_segments = 64;         // give up on longer walks
  double search_radius = 10.0;   // m; farthest curve considered
};

// The cycle (boundary in walk order), or nullopt when no closed walk exists.
std::optional<std::vector<OrientedSegment>> manual_cycle(const Network& network, const Vec3& point,
                                                         const ManualPatchParams& params);

// The patch whose mesh (or, without a mesh, boundary nodes) is nearest to
// `point`; nullopt when there is no patch.
std::optional<PatchId> nearest_patch(const Network& network, const Vec3& point);

// Distance from p to the triangle (a, b, c).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace sketchlab::soapfilm
