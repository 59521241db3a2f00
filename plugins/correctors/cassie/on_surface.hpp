#pragma once
// On-surface strokes (thesis §3.3.5; CASSIE app item 20): strokes drawn on a
// patch are projected onto its mesh.
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
  bool whole = false;                // every control point near the patch, else the ends only
};

// Item 20 (`Beautifier.ProjectOnSurfaces`). The patch is the first (by id)
// the brush touched: with `brush` (hand positions away from every curve's
// collider), one of them within `brush_radius` of its mesh; without it, a
// control point within `max_distance` of its mesh. The whole stroke (each control point within `max_distance`) is
// projected when the patch spans it (its box grown by max_distance holds
// every control point), every constrained anchor (`anchors`: control point
// indices) is on the patch (within max_distance) and the stroke meets the
// patch's boundary curves at most once (`intersections`: the curves met);
// otherwise only the two ends, when within max_distance. No test against the
// patch normal. nullopt when no patch is near.
std::optional<SurfaceProjection> project_on_surface(const Network& network,
                                                    const std::vector<Vec3>& points,
                                                    const std::vector<int>& anchors,
                                                    const std::vector<CurveId>& intersections,
                                                    double max_distance,
                                                    const std::vector<Vec3>* brush = nullptr,
                                                    double brush_radius = 0.0);

}  // namespace sketchlab::cassie
