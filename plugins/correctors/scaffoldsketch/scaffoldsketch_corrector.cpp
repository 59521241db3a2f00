#include "scaffoldsketch_corrector.hpp"

#include "scaffold_line.hpp"
#include "shape_stroke.hpp"
#include "sketchlab/geometry/polyline.hpp"

namespace sketchlab::scaffoldsketch {

std::vector<ParamSpec> parameter_specs() {
  const ScaffoldParams s;
  const ShapeParams h;
  const PreprocessParams p;
  return {
      {"point_distance", ParamType::real, s.point_distance, 0.001, 1.0, {}, "m",
       "point–point and point–line inclusion distance at zoom 1, §4.1 eq. 1–2 (5 cm)"},
      {"angle_threshold", ParamType::real, s.angle_threshold / degrees, 0.1, 45.0, {}, "deg",
       "perpendicular / parallel inclusion angle, §4.1 eq. 3–4 (10°)"},
      {"equal_length_tolerance", ParamType::real, s.equal_length_tolerance, 0.0, 1.0, {}, "",
       "relative length difference for equal length, §4.1 eq. 5 (25 %)"},
      {"point_point_weight", ParamType::real, s.point_point_weight, 1e-6, 1e6, {}, "",
       "initial IRLS weight of point–point constraints, §4.1 (100)"},
      {"other_weight", ParamType::real, s.other_weight, 1e-6, 1e6, {}, "",
       "initial IRLS weight of the other constraints, §4.1 (1)"},
      {"epsilon", ParamType::real, s.epsilon, 1e-20, 1e-2, {}, "",
       "ε of eq. 7; C <= ε counts as satisfied (paper: unspecified; 1e-12)"},
      {"max_iterations", ParamType::integer, std::int64_t{s.max_iterations}, 1, 1000, {}, "",
       "IRLS rounds at most (paper observes 2–6)"},
      {"tick_length", ParamType::real, s.tick_length, 0.0, 0.5, {}, "m",
       "scaffold strokes shorter than this (at zoom 1) are ticks, §3.2 (3 cm)"},
      {"midpoint_snapping", ParamType::boolean, s.midpoint_snapping, {}, {}, {}, "",
       "the new line's midpoint keypoint also takes point–point constraints, §4.1"},
      {"vertical_parallel", ParamType::boolean, s.vertical_parallel, {}, {}, {}, "",
       "parallel-to-vertical-axis (workspace.up) candidate, §4.1 eq. 4"},
      {"vertical_perpendicular", ParamType::boolean, s.vertical_perpendicular, {}, {}, {}, "",
       "perpendicular-to-vertical-axis (horizontal) candidate, §4.1 eq. 3 with d = up"},
      {"node_tolerance", ParamType::real, s.node_tolerance, 0.0, 0.01, {}, "m",
       "a corrected end within this of a curve becomes a Node"},
      {"point_line_reach", ParamType::choice, std::string("line"), {}, {}, {"line", "segment"}, "",
       "point–line candidates for ends near a scaffold line's infinite extension (eq. 2, "
       "authors) or near the segment only"},
      {"direction_only_length", ParamType::choice, std::string("drawn"), {}, {},
       {"drawn", "nearest"}, "",
       "a line kept only by direction terms keeps its drawn length (authors; eq. 6's gradient) "
       "or becomes the nearest such line (L·cos θ)"},
      {"sample_spacing", ParamType::real, h.sample_spacing, 0.001, 0.1, {}, "m",
       "shape stroke resampling step, §4.2.1 (1 cm)"},
      {"keypoint_distance", ParamType::real, h.keypoint_distance, 0.001, 0.5, {}, "m",
       "shape samples pick the nearest scaffold keypoint within this, §4.2.1 (3 cm)"},
      {"tangent_angle", ParamType::real, h.tangent_angle / degrees, 0.0, 90.0, {}, "deg",
       "snap a keypoint tangent to a scaffold line within this angle, §4.2.1 (25°)"},
      {"straight_deviation", ParamType::real, h.straight_deviation, 0.0, 1.0, {}, "",
       "PCA straightness: max distance / PCA length, §4.2.2 (8 %)"},
      {"straight_length_tolerance", ParamType::real, h.straight_length_tolerance, 0.0, 1.0, {},
       "", "PCA length within this fraction of the arclength, §4.2.2 (10 %)"},
      {"samples_per_segment", ParamType::integer, std::int64_t{h.samples_per_segment}, 2, 200,
       {}, "", "mean arclength samples per Bézier segment for eq. 8–9 (at least 2 each)"},
      {"straight_shape", ParamType::choice, std::string("line"), {}, {}, {"line", "polyline"}, "",
       "a straight shape stroke becomes one line between its first and last keypoints "
       "(§4.2.2) or a polyline through every keypoint (authors)"},
      {"tangent_sample", ParamType::choice, std::string("closest"), {}, {}, {"closest", "best"},
       "",
       "a keypoint's tangent is matched at the sample closest to it (§4.2.1) or best over "
       "every sample that selected it (authors)"},
      {"tangent_curvature", ParamType::boolean, h.tangent_curvature, {}, {}, {}, "",
       "eq. 9 also compares, at each keypoint, the curvature of the circle tangent to its "
       "constrained direction (no hooks); false: eq. 8 at arclength samples only"},
      {"max_evaluations", ParamType::integer, std::int64_t{h.max_evaluations}, 10, 1000000, {},
       "", "NLopt objective evaluations per MVC solve"},
      {"delta", ParamType::real, p.delta, 0.001, 0.5, {}, "m",
       "kernel preprocessing δ (line detection for automatic strokes, freehand fallback)"},
  };
}

ScaffoldSketchCorrector::ScaffoldSketchCorrector(const Params& p) {
  scaffold_.point_distance = p.real("point_distance");
  scaffold_.angle_threshold = p.real("angle_threshold") * degrees;
  scaffold_.equal_length_tolerance = p.real("equal_length_tolerance");
  scaffold_.point_point_weight = p.real("point_point_weight");
  scaffold_.other_weight = p.real("other_weight");
  scaffold_.epsilon = p.real("epsilon");
  scaffold_.max_iterations = static_cast<int>(p.integer("max_iterations"));
  scaffold_.tick_length = p.real("tick_length");
  scaffold_.midpoint_snapping = p.boolean("midpoint_snapping");
  scaffold_.vertical_parallel = p.boolean("vertical_parallel");
  scaffold_.vertical_perpendicular = p.boolean("vertical_perpendicular");
  scaffold_.node_tolerance = p.real("node_tolerance");
  scaffold_.point_line_reach =
      p.string("point_line_reach") == "line" ? PointLineReach::line : PointLineReach::segment;
  scaffold_.direction_only_length = p.string("direction_only_length") == "drawn"
                                        ? DirectionOnlyLength::drawn
                                        : DirectionOnlyLength::nearest;
  shape_.sample_spacing = p.real("sample_spacing");
  shape_.keypoint_distance = p.real("keypoint_distance");
  shape_.tangent_angle = p.real("tangent_angle") * degrees;
  shape_.straight_deviation = p.real("straight_deviation");
  shape_.straight_length_tolerance = p.real("straight_length_tolerance");
  shape_.samples_per_segment = static_cast<int>(p.integer("samples_per_segment"));
  shape_.straight_shape =
      p.string("straight_shape") == "line" ? StraightShape::line : StraightShape::polyline;
  shape_.tangent_sample =
      p.string("tangent_sample") == "closest" ? TangentSample::closest : TangentSample::best;
  shape_.tangent_curvature = p.boolean("tangent_curvature");
  shape_.max_evaluations = static_cast<int>(p.integer("max_evaluations"));
  preprocess_.delta = p.real("delta");
  // Automatic strokes are lines by shape alone (chord/length >= 0.98):
  // imported sessions carry synthetic sample times, so the speed test of
  // CASSIE's line detection would reject every stroke.
  preprocess_.line_min_speed = 0;
}

ScaffoldSketchCorrector::ScaffoldSketchCorrector(const ScaffoldParams& scaffold,
                                                 const ShapeParams& shape,
                                                 const PreprocessParams& preprocess)
    : scaffold_(scaffold), shape_(shape), preprocess_(preprocess) {
  preprocess_.line_min_speed = 0;  // see the constructor above
}

Correction ScaffoldSketchCorrector::correct(const Stroke& stroke, const Sketch& sketch) {
  if (stroke.is_2d()) {
    Correction c;
    c.error = "stroke " + std::to_string(stroke.id) +
              ": scaffoldsketch corrects 3D (VR) strokes only, this one is in pixels";
    return c;
  }
  const double scale = stroke.workspace_scale > 0 ? stroke.workspace_scale : 1.0;
  const std::vector<Vec3> points = positions(stroke);
  if (points.empty()) {
    Correction c;
    c.error = "stroke " + std::to_string(stroke.id) + " has no samples";
    return c;
  }
  Vec3 a = points.front(), b = points.back();  // press and release (§3.2)
  StrokeMode mode = StrokeMode::shape;
  switch (stroke.layer) {
    case Layer::scaffold:
    case Layer::guide: mode = StrokeMode::scaffold; break;
    case Layer::shape: mode = StrokeMode::shape; break;
    case Layer::free:
    case Layer::automatic: {
      if (polyline_length(points) < scaled_threshold(scaffold_.tick_length, scale)) {
        mode = StrokeMode::scaffold;  // too short to be a shape: a tick
        break;
      }
      const Preprocessed pre = preprocess_stroke(stroke, preprocess_);
      if (pre.is_line) {
        mode = StrokeMode::scaffold;
        a = pre.curve.control_points.front();  // hooks cut
        b = pre.curve.control_points.back();
      }
      break;
    }
  }
  if (mode == StrokeMode::shape)
    return correct_shape_stroke(stroke, sketch, shape_, scaffold_.node_tolerance, preprocess_);
  if (polyline_length(points) < scaled_threshold(scaffold_.tick_length, scale) ||
      (b - a).norm() <= 0.0)
    return correct_tick(points, stroke.id, sketch, scaffold_, scale);
  return correct_scaffold_line(a, b, stroke.id, sketch, scaffold_, scale);
}

}  // namespace sketchlab::scaffoldsketch
