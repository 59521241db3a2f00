#include "scaffoldsketch_corrector.hpp"

#include "scaffold_line.hpp"
#include "shape_stroke.hpp"
#include "sketchlab/geometry/polyline.hpp"
#include "sketchlab/plugin/param_table.hpp"

namespace sketchlab::scaffoldsketch {

namespace {

// Everything the plugin's parameters set, one struct per stage.
struct Settings {
  ScaffoldParams scaffold;
  ShapeParams shape;
  PreprocessParams preprocess;
};

const ParamTable<Settings>& parameters() {
  auto sc = [](auto field) { return nested_field(&Settings::scaffold, field); };
  auto sh = [](auto field) { return nested_field(&Settings::shape, field); };
  using S = ScaffoldParams;
  using H = ShapeParams;
  static const auto table =
      ParamTable<Settings>()
          .real("point_distance", sc(&S::point_distance), 0.001, 1.0, "m",
                "point–point and point–line inclusion distance at zoom 1, §4.1 eq. 1–2 (5 cm)")
          .real("angle_threshold", sc(&S::angle_threshold), 0.1, 45.0, "deg",
                "perpendicular / parallel inclusion angle, §4.1 eq. 3–4 (10°)", degrees)
          .real("equal_length_tolerance", sc(&S::equal_length_tolerance), 0.0, 1.0, "",
                "relative length difference for equal length, §4.1 eq. 5 (25 %)")
          .real("point_point_weight", sc(&S::point_point_weight), 1e-6, 1e6, "",
                "initial IRLS weight of point–point constraints, §4.1 (100)")
          .real("other_weight", sc(&S::other_weight), 1e-6, 1e6, "",
                "initial IRLS weight of the other constraints, §4.1 (1)")
          .real("epsilon", sc(&S::epsilon), 1e-20, 1e-2, "",
                "ε of eq. 7; C <= ε counts as satisfied (paper: unspecified; 1e-12)")
          .integer("max_iterations", sc(&S::max_iterations), 1, 1000, "",
                   "IRLS rounds at most (paper observes 2–6)")
          .real("tick_length", sc(&S::tick_length), 0.0, 0.5, "m",
                "scaffold strokes shorter than this (at zoom 1) are ticks, §3.2 (3 cm)")
          .boolean("midpoint_snapping", sc(&S::midpoint_snapping),
                   "the new line's midpoint keypoint also takes point–point constraints, §4.1")
          .boolean("vertical_parallel", sc(&S::vertical_parallel),
                   "parallel-to-vertical-axis (workspace.up) candidate, §4.1 eq. 4")
          .boolean("vertical_perpendicular", sc(&S::vertical_perpendicular),
                   "perpendicular-to-vertical-axis (horizontal) candidate, §4.1 eq. 3 with d = up")
          .real("node_tolerance", sc(&S::node_tolerance), 0.0, 0.01, "m",
                "a corrected end within this of a curve becomes a Node")
          .choice("point_line_reach", sc(&S::point_line_reach),
                  std::vector<std::pair<std::string, PointLineReach>>{{"line", PointLineReach::line},
                                                                      {"segment", PointLineReach::segment}},
                  "point–line candidates for ends near a scaffold line's infinite extension (eq. 2, "
                  "authors) or near the segment only")
          .choice("direction_only_length", sc(&S::direction_only_length),
                  std::vector<std::pair<std::string, DirectionOnlyLength>>{
                      {"drawn", DirectionOnlyLength::drawn}, {"nearest", DirectionOnlyLength::nearest}},
                  "a line kept only by direction terms keeps its drawn length (authors; eq. 6's gradient) "
                  "or becomes the nearest such line (L·cos θ)")
          .real("sample_spacing", sh(&H::sample_spacing), 0.001, 0.1, "m",
                "shape stroke resampling step, §4.2.1 (1 cm)")
          .real("keypoint_distance", sh(&H::keypoint_distance), 0.001, 0.5, "m",
                "shape samples pick the nearest scaffold keypoint within this, §4.2.1 (3 cm)")
          .real("tangent_angle", sh(&H::tangent_angle), 0.0, 90.0, "deg",
                "snap a keypoint tangent to a scaffold line within this angle, §4.2.1 (25°)", degrees)
          .real("straight_deviation", sh(&H::straight_deviation), 0.0, 1.0, "",
                "PCA straightness: max distance / PCA length, §4.2.2 (8 %)")
          .real("straight_length_tolerance", sh(&H::straight_length_tolerance), 0.0, 1.0, "",
                "PCA length within this fraction of the arclength, §4.2.2 (10 %)")
          .integer("samples_per_segment", sh(&H::samples_per_segment), 2, 200, "",
                   "mean arclength samples per Bézier segment for eq. 8–9 (at least 2 each)")
          .choice("straight_shape", sh(&H::straight_shape),
                  std::vector<std::pair<std::string, StraightShape>>{{"line", StraightShape::line},
                                                                     {"polyline", StraightShape::polyline}},
                  "a straight shape stroke becomes one line between its first and last keypoints "
                  "(§4.2.2) or a polyline through every keypoint (authors)")
          .choice("tangent_sample", sh(&H::tangent_sample),
                  std::vector<std::pair<std::string, TangentSample>>{{"closest", TangentSample::closest},
                                                                     {"best", TangentSample::best}},
                  "a keypoint's tangent is matched at the sample closest to it (§4.2.1) or best over "
                  "every sample that selected it (authors)")
          .boolean("tangent_curvature", sh(&H::tangent_curvature),
                   "eq. 9 also compares, at each keypoint, the curvature of the circle tangent to its "
                   "constrained direction (no hooks); false: eq. 8 at arclength samples only")
          .integer("max_evaluations", sh(&H::max_evaluations), 10, 1000000, "",
                   "NLopt objective evaluations per MVC solve")
          .real("delta", nested_field(&Settings::preprocess, &PreprocessParams::delta), 0.001, 0.5, "m",
                "kernel preprocessing δ (line detection for automatic strokes, freehand fallback)");
  return table;
}

}  // namespace

std::vector<ParamSpec> parameter_specs() { return parameters().specs(); }

ScaffoldSketchCorrector::ScaffoldSketchCorrector(const Params& p) {
  const Settings s = parameters().read(p);
  scaffold_ = s.scaffold;
  shape_ = s.shape;
  preprocess_ = s.preprocess;
  preprocess_.line_min_speed = 0;  // see the constructor below
}

ScaffoldSketchCorrector::ScaffoldSketchCorrector(const ScaffoldParams& scaffold,
                                                 const ShapeParams& shape,
                                                 const PreprocessParams& preprocess)
    : scaffold_(scaffold), shape_(shape), preprocess_(preprocess) {
  // Automatic strokes are lines by shape alone (chord/length >= 0.98):
  // imported sessions carry synthetic sample times, so the speed test of
  // CASSIE's line detection would reject every stroke.
  preprocess_.line_min_speed = 0;
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
