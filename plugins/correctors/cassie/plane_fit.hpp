#pragma once
// The plane of a stroke's control points (thesis §3.2.3.2 "Planarity"; CASSIE
// app item 14).
#include <vector>

#include "sketchlab/geometry/plane.hpp"  // plane_residual
#include "sketchlab/types.hpp"

namespace sketchlab::cassie {

struct PlaneFit {
  bool planar = false;  // farthest control point within max_distance of the tested plane
  Vec3 normal = Vec3::UnitZ();
  Vec3 centroid = Vec3::Zero();
  double max_distance = 0.0;  // of the points to the tested plane
  int axis = -1;  // 0,1,2 when the normal was snapped to that axis (within the angle)
};

// Least-squares plane through the points (at least 3, not collinear; else
// planar = false); the normal is snapped to the first axis within `angle`.
// `test_snapped`: the distance test is against the snapped plane, else
// against the least-squares one (CHI 2021 §4.2 "Planarity": fit, test the
// farthest point, then snap).
PlaneFit fit_plane(const std::vector<Vec3>& points, double max_distance, double angle, bool test_snapped);

}  // namespace sketchlab::cassie
