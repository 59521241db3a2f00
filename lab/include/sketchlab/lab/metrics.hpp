#pragma once
// Summary metrics of one replayed case (DESIGN.md "Experiments").
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sketchlab/lab/stack.hpp"

namespace sketchlab {

struct MetricsOptions {
  // Endpoint snap test for the reference comparison, and relation detection
  // for ground truth: a relation holds in the output when its measure is
  // below these tolerances.
  double distance_tolerance = 1e-3;           // m
  double angle_tolerance = 0.5 * 3.14159265358979 / 180.0;  // rad
  double length_tolerance = 0.01;             // relative, equal lengths
  int resample = 32;                          // points per curve for deviations
};

struct PrecisionRecall {
  std::size_t intended = 0, detected = 0, matched = 0;
  double precision() const { return detected ? double(matched) / detected : 1.0; }
  double recall() const { return intended ? double(matched) / intended : 1.0; }
};

// All metrics of a case, by name, plus relation precision/recall by kind.
// Names (absent when not applicable):
//   latency_p50_ms, latency_p95_ms, latency_max_ms (corrected strokes)
//   strokes (live strokes with curves), curves, nodes, patches, events_refused
//   dangling_endpoint_ratio: curve ends not at a node over all network nodes
//     (nodes + dangling ends), CASSIE CHI 2021 §6.4.2
//   input_deviation_mean_m, input_deviation_max_m: distance of each live 3D
//     stroke's samples to its curve
//   input_hausdorff_mean_m, input_hausdorff_max_m: two-sided (Hausdorff)
//     distance between each live 3D stroke's samples and its curve
//     (geometry/hausdorff.hpp)
//   enforced_<kind>_residual_mean: mean residual of enforced constraints
//   ref_<track>_endpoint_mean_m, ref_<track>_control_mean_m,
//   ref_<track>_snap_agreement, ref_<track>_compared: against a reference
//     track (matching by source stroke)
//   gt_distance_mean_m, gt_distance_max_m: output curves vs the intended
//     ("ground_truth" track) curves, raw
//   gt_shape_distance_mean_m, gt_shape_coverage_mean_m: the output against
//     the intended shape as a whole: each output sample to the nearest
//     intended curve of any live stroke, and each intended sample to the
//     nearest output curve (a curve built from several strokes is scored
//     against all of them); with _aligned_eye_scale_m instead of _m, the
//     same after the eye-scale alignment below
//   gt_distance_mean_aligned_eye_scale_m, gt_distance_max_aligned_eye_scale_m,
//   gt_eye_scale: the same after the best uniform scaling of the output about
//     the camera eye (gt_eye_scale = that factor), which leaves every pixel of
//     the view unchanged: the depth/scale one view cannot determine. Present
//     only when every stroke of the session (kept or not) is a 2D stroke seen
//     from one eye (with two or more eye positions the views fix the scale:
//     use the raw figure)
//   gt_<kind>_precision, gt_<kind>_recall: relations of the track's
//     RelationEvents against those measured on the output over all pairs of
//     live strokes (touching within distance_tolerance, of the eye-scaled
//     output where that alignment is present: coincident_point when
//     at both curves' ends, else intersection; parallel, equal_length among
//     straight curves; perpendicular among touching straight curves; planar
//     for single non-straight curves). Parallel and equal_length are compared
//     as equivalence classes. Precision is absent when nothing was detected.
struct CaseMetrics {
  std::map<std::string, double> values;
  std::map<std::string, PrecisionRecall> relations;  // by constraint kind name
};

CaseMetrics compute_metrics(const ReplayResult& result, const MetricsOptions& options = {});

}  // namespace sketchlab
