#pragma once
// User-guided patches (CHI'21 §5.1, thesis §3.3.3): from the segment closest
// to a point, walk the graph always taking the segment whose closest point
// is nearest to that point, until back at the start node. Segments that
// already bound two patches are allowed (non-manifold on purpose); the CASSIE
// app's turn limit and "manifold first" (item 26) are parameters.
#include <optional>
#include <vector>

#include "sketchlab/network.hpp"

namespace sketchlab::soapfilm {

struct ManualPatchParams {
  int max_segments = 64;         // give up on longer walks
  double search_radius = 10.0;   // m; farthest curve considered
  // CASSIE app, item 26: the walk gives up after this many turns where the
  // arriving and leaving tangents differ (cos < turn_cos); 0: no limit.
  int max_turns = 10;
  double turn_cos = 0.8;
  // Item 26's "manifold first": among the segments at a node, those bounding
  // fewer than two patches are taken before the nearer others.
  bool manifold_first = false;
};

// The cycle (boundary in walk order), or nullopt when no closed walk exists.
// `closed_seam_nodes`: the graph's (CurveGraph).
std::optional<std::vector<OrientedSegment>> manual_cycle(const Network& network, const Vec3& point,
                                                         const ManualPatchParams& params, bool closed_seam_nodes);

// The patch whose mesh (or, without a mesh, boundary nodes) is nearest to
// `point`; nullopt when there is no patch.
std::optional<PatchId> nearest_patch(const Network& network, const Vec3& point);

// Distance from p to the triangle (a, b, c).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace sketchlab::soapfilm
