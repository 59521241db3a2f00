#pragma once
// Sharp feature curves of a triangle (or polygon) mesh: the edges whose
// dihedral angle exceeds a threshold, chained into polylines, as a
// ground-truth network (what a designer would draw of a CAD part).
#include <filesystem>
#include <string>
#include <vector>

#include "ground_truth.hpp"

namespace sketchlab::synthetic {

struct MeshFeatureParams {
  // An edge is a feature when the angle between its two faces' normals
  // exceeds this (rad); boundary edges always are.
  double feature_angle = 0.5235987755982988;  // 30°
  // Chains are split at vertices where they turn by more than this (rad), so
  // each stroke is smooth (the kernel's sharp-joint threshold).
  double corner_angle = 0.7853981633974483;  // 45°
};

// Feature polylines of the mesh in `path` (OFF or PLY, read with OpenMesh), in
// the mesh's own coordinates. Chains start at vertices where the number of
// feature edges is not 2 (in vertex order), then the remaining closed loops
// (first point repeated at the end). Throws std::runtime_error naming the
// file when it cannot be read or has no faces.
std::vector<std::vector<Vec3>> mesh_feature_polylines(const std::filesystem::path& path,
                                                      const MeshFeatureParams& params = {});

// Polylines -> network of shape curves: straight chains (all points within
// 1e-9 of the chord, relative) become lines; others a poly-Bézier with one
// straight cubic per polyline edge (joints sharp where the turn exceeds 45°),
// closed if the chain is. The whole set is scaled uniformly so its largest
// bounding-box extent is `size` metres and centred at `center`.
GroundTruthNetwork feature_network(const std::vector<std::vector<Vec3>>& polylines,
                                   const Vec3& center, double size, const std::string& name);

}  // namespace sketchlab::synthetic
