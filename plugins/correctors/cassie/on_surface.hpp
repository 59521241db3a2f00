#pragma once
// On-surface strokes (thesis §3.3.5; CASSIE app item 20): strokes drawn on a
// patch are projected onto its mesh.
#include <array>
#include <optional>
#include <set>
#include <vector>

#include "cassie_params.hpp"
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

// The hand during the stroke (items 6, 20). Positions in metres.
struct SurfaceBrush {
  // Hand positions away from every curve's collider; nullptr: the patch is
  // touched by a control point within max_distance instead.
  const std::vector<Vec3>* away = nullptr;
  std::array<Vec3, 2> ends{Vec3::Zero(), Vec3::Zero()};  // the stroke's first and last hand positions
  double radius = 0.0;                                    // the brush's
  SurfaceSpan span = SurfaceSpan::box;
};

// Item 20 (`Beautifier.ProjectOnSurfaces`). The patch is the first (by id)
// the brush touched: with `brush.away`, one of them within `brush.radius` of
// its mesh; without it, a control point within `max_distance` of its mesh.
// The whole stroke (each control point within `max_distance`) is projected
// when the patch spans it (`brush.span`), every constrained anchor
// (`anchors`: control point indices) is on the patch (within max_distance)
// and the stroke meets the patch's boundary curves at most once
// (`intersections`: the curves met); otherwise only the two ends, when within
// max_distance. No test against the patch normal. nullopt when no patch is
// near.
std::optional<SurfaceProjection> project_on_surface(const Network& network,
                                                    const std::vector<Vec3>& points,
                                                    const std::vector<int>& anchors,
                                                    const std::vector<CurveId>& intersections,
                                                    double max_distance, const SurfaceBrush& brush);

}  // namespace sketchlab::cassie
