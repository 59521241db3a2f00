#pragma once
// Surface normal at a node (CASSIE thesis §3.3.2.1 "Defining normals at
// nodes", CHI'21 §5.1): the normal of the plane through the node that best
// fits the tangents of the incident segments.
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab::soapfilm {

struct NodeFrameParams {
  // Plane-fit error above which a node is sharp (thesis §3.3.2.2: ε_sharp = 0.3).
  double sharp_error = 0.3;
  // CHI'21 §5.1: sharp if max_i |n_P · t_i| > cos(π/2 − θ), θ the small angle
  // of §4.4 (CASSIE: π/6).
  double sharp_angle = 0.5235987755982988;
};

struct NodeFrame {
  Vec3 normal = Vec3::Zero();  // unit; sign fixed by a deterministic rule only
  bool defined = false;        // false when the tangents do not span a plane
  bool sharp = false;
  double fit_error = 0.0;      // RMS distance of the unit tangents to the plane
  double max_offset = 0.0;     // max_i |n · t_i|
};

// `directions`: unit tangents leaving the node along each incident segment.
// The plane through the origin minimising Σ (n·t_i)² (smallest eigenvector of
// Σ t_i t_iᵀ). Undefined with fewer than 2 non-collinear directions.
NodeFrame fit_node_frame(const std::vector<Vec3>& directions, const NodeFrameParams& params);

}  // namespace sketchlab::soapfilm
