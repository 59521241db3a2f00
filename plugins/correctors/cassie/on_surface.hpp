#pragma once
// On-surface strokes (thesis §3.3.5): a stroke whose control points all lie
// near one patch, whose end tangents are not within θ of the patch normal,
// and which does not split the patch's boundary cycle, is projected onto it.
#include <optional>
#include <set>
#include <vector>

#include "sketchlab/network.hpp"

namespace sketchlab::cassie {

struct MeshPoint {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit face normal
  double distance = 0.0;
};

// Closest point of a triangle mesh to p (brute force over faces); nullopt
// for a mesh without faces.
std::optional<MeshPoint> closest_on_mesh(const Mesh& mesh, const Vec3& p);

struct SurfaceProjection {
  PatchId patch = 0;
  std::vector<Vec3> control_points;  // projected
};

// `points`: the corrected control points; t0, t1: unit tangents at the ends;
// `boundary_hits`: curves the stroke was connected to (a stroke meeting the
// patch boundary at two or more places would split its cycle). First patch
// (by id) that qualifies.
std::optional<SurfaceProjection> project_on_surface(const Network& network,
                                                    const std::vector<Vec3>& points,
                                                    const Vec3& t0, const Vec3& t1,
                                                    const std::vector<CurveId>& boundary_hits,
                                                    double max_distance, double angle);

}  // namespace sketchlab::cassie
