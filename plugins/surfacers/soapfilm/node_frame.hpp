#pragma once
// Surface normal at a node (CASSIE thesis §3.3.2.1 "Defining normals at
// nodes", CHI'21 §5.1): the normal of the plane best fitting the tangents of
// the incident segments. As in the CASSIE app (item 23, Node.UpdateNormal,
// Utils.FitPlane): the plane is fitted through the centroid of the points
// {P, P + t_i}; when the tangents are nearly collinear the directions towards
// the segments' opposite nodes are fitted instead; a node is sharp when some
// tangent leaves the plane by more than θ (the tangents, also when the plane
// was fitted to the opposite nodes: item 23's test is max |n·t|).
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab::soapfilm {

struct NodeFrameParams {
  // CHI'21 §5.1: sharp if max_i |n_P · t_i| > cos(π/2 − θ), θ the small angle
  // of §4.4 (CASSIE: π/6, i.e. |n·t| > 0.5 as in the app, item 23).
  double sharp_angle = 0.5235987755982988;
  // Thesis §3.3.2.2 also calls a node sharp when the plane-fit error (RMS
  // distance of the fitted points to the plane) exceeds ε_sharp = 0.3; the
  // app has no such test (item 23). The error of unit directions stays well
  // below 1, so 1 (the default) disables it.
  double sharp_error = 1.0;
  // Item 23: tangents are "nearly collinear" when the largest |t_i × t_j| is
  // below this.
  double collinear = 0.1;
};

struct NodeFrame {
  Vec3 normal = Vec3::Zero();  // unit; sign fixed by a deterministic rule only
  bool defined = false;        // false when the fitted directions do not span a plane
  bool sharp = false;
  bool from_opposite = false;  // fitted to the directions towards the opposite nodes
  double fit_error = 0.0;      // RMS distance of {0, d_i} to the fitted plane
  double max_offset = 0.0;     // max_i |n · t_i| over the unit tangents t_i (item 23's sharp test)
};

// `tangents`: unit tangents leaving the node along each incident segment;
// `opposite`: for each, the unit direction from the node towards the
// segment's other node (same order and size; a zero vector where there is
// none, e.g. a loop). Undefined with fewer than 2 directions or when neither
// set spans a plane.
NodeFrame fit_node_frame(const std::vector<Vec3>& tangents, const std::vector<Vec3>& opposite,
                         const NodeFrameParams& params);

}  // namespace sketchlab::soapfilm
