#pragma once
// Parameters of the ScaffoldSketch auto-correct (Yu et al., UIST 2021), with
// the paper's defaults. Distances are metres at zoom 1 and scale as δ/s.
#include <numbers>

namespace sketchlab::scaffoldsketch {

inline constexpr double degrees = std::numbers::pi / 180.0;

// Where the paper and the authors' implementation differ (issue #18), the
// authors' behaviour is a choice; each default is what the paper implies
// (README, "Paper and authors' code").

// Which end positions take a point–line candidate (eq. 2).
enum class PointLineReach {
  line,     // within point_distance of the scaffold line's infinite extension (eq. 2; authors)
  segment,  // within point_distance of the scaffold segment itself
};

// The length of a line whose kept terms are all directions (eq. 3–4), which
// leave it free.
enum class DirectionOnlyLength {
  drawn,    // the drawn length, about the drawn midpoint (authors; eq. 6's gradient keeps it)
  nearest,  // the nearest such line to the drawn one (its projection: L·cos θ)
};

// The output of an approximately straight shape stroke (§4.2.2).
enum class StraightShape {
  line,      // one exact line between the first and last keypoints (paper)
  polyline,  // straight segments through every keypoint (authors)
};

// Which samples of a shape stroke choose a keypoint's tangent (§4.2.1).
enum class TangentSample {
  closest,  // the sample closest to the keypoint (paper: "the input curve's tangent")
  best,     // the best-aligned of all samples that selected the keypoint (authors)
};

// §4.1, scaffold lines.
struct ScaffoldParams {
  double point_distance = 0.05;          // m: point–point and point–line inclusion (eq. 1, 2)
  double angle_threshold = 10 * degrees;  // rad: perpendicular / parallel inclusion (eq. 3, 4)
  double equal_length_tolerance = 0.25;  // relative length difference for eq. 5
  double point_point_weight = 100.0;     // initial IRLS weight of point–point terms
  double other_weight = 1.0;             // initial IRLS weight of the other terms
  double epsilon = 1e-12;                // ε of eq. 7 (units of C); C <= ε counts as satisfied
  int max_iterations = 50;               // IRLS rounds at most
  double tick_length = 0.03;             // m: shorter scaffold strokes are ticks (§3.2)
  bool midpoint_snapping = true;         // the new line's midpoint l_m also takes point–point terms
  bool vertical_parallel = true;         // parallel-to-up candidate (eq. 4 with d = workspace.up)
  bool vertical_perpendicular = true;    // perpendicular-to-up candidate (eq. 3 with d = workspace.up)
  double node_tolerance = 1e-6;          // m: an endpoint this close to a curve makes a Node
  PointLineReach point_line_reach = PointLineReach::line;
  DirectionOnlyLength direction_only_length = DirectionOnlyLength::drawn;
};

// §4.2, shape strokes.
struct ShapeParams {
  double sample_spacing = 0.01;           // m: arclength resampling of the input (§4.2.1)
  double keypoint_distance = 0.03;        // m: nearest scaffold keypoint within this (§4.2.1)
  double tangent_angle = 25 * degrees;    // rad: snap to a scaffold tangent below this (§4.2.1)
  double straight_deviation = 0.08;       // PCA straightness: max distance / PCA length (§4.2.2)
  double straight_length_tolerance = 0.10;  // PCA length within this of the arclength (§4.2.2)
  int samples_per_segment = 8;            // mean arclength samples per Bézier segment (eq. 8–9)
  bool tangent_curvature = true;          // eq. 9 also sees each keypoint's tangent circle (ours)
  int max_evaluations = 3000;             // NLopt objective evaluations per solve
  StraightShape straight_shape = StraightShape::line;
  TangentSample tangent_sample = TangentSample::closest;
};

}  // namespace sketchlab::scaffoldsketch
