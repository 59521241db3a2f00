#include "shape_stroke.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "mvc_curve.hpp"
#include "sketchlab/network_curve.hpp"
#include "sketchlab/network_nodes.hpp"
#include "scaffold_line.hpp"
#include "shape_keypoints.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/polyline.hpp"
#include "sketchlab/preprocess/line_detection.hpp"
#include "sketchlab/session.hpp"

namespace sketchlab::scaffoldsketch {

namespace {

// Straight segments through `points` (distinct neighbours), sharp at every
// inner joint; the line itself for two points.
Curve polyline_curve(const std::vector<Vec3>& points) {
  if (points.size() == 2) return make_line(points.front(), points.back());
  Curve c;
  c.kind = CurveKind::bezier;
  c.control_points.push_back(points.front());
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const Vec3 e = points[k + 1] - points[k];
    c.control_points.push_back(points[k] + e / 3.0);
    c.control_points.push_back(points[k] + 2.0 * e / 3.0);
    c.control_points.push_back(points[k + 1]);
  }
  c.sharp.assign(points.size(), true);
  c.sharp.front() = c.sharp.back() = false;
  return c;
}

}  // namespace

std::vector<Vec3> resample_every(const std::vector<Vec3>& points, double spacing) {
  std::vector<Vec3> distinct;
  for (const Vec3& p : points)
    if (distinct.empty() || (p - distinct.back()).norm() > 0) distinct.push_back(p);
  if (distinct.size() < 2) return distinct;
  const double length = polyline_length(distinct);
  // Issue 17: at most 10^5 samples, whatever the length (a glitch sample
  // 1000 km away asked for 10^9 and the memory to hold them).
  const double wanted = std::ceil(length / spacing) + 1;
  const int n = static_cast<int>(std::clamp(wanted, 2.0, 1e5));
  return resample_polyline(distinct, n);
}

Correction correct_shape_stroke(const Stroke& stroke, const Sketch& sketch,
                                const ShapeParams& params, double node_tolerance,
                                const PreprocessParams& fallback) {
  const auto start = std::chrono::steady_clock::now();
  Correction out;
  auto finish = [&](const char* mode) {
    out.stats.outcomes["mode"] = mode;
    out.stats.extra["time_ms"] =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count();
    return out;
  };
  const double scale = stroke.workspace_scale;
  const std::vector<Vec3> raw = positions(stroke);
  const std::vector<Vec3> samples =
      resample_every(raw, scaled_threshold(params.sample_spacing, scale));
  if (samples.size() < 2) {
    out.error = "stroke " + std::to_string(stroke.id) + " has zero length";
    return out;
  }
  const Network& network = sketch.network;
  const ShapeKeypoints keys = select_shape_keypoints(samples, network, params, scale);
  const std::size_t m = keys.points.size();
  out.stats.extra["keypoints"] = static_cast<double>(m);
  if (m < 2) {
    out.edit = freehand_edit(stroke, sketch, fallback);
    if (!out.edit.curves_added.empty()) out.edit.curves_added.front().layer = Layer::shape;
    return finish(mode_shape_fallback);
  }

  Curve shape;
  const PcaLine pca =
      fit_pca_line(samples, params.straight_deviation, params.straight_length_tolerance);
  const bool straight = pca.is_line && (keys.points.back() - keys.points.front()).norm() > 1e-12;
  // §4.2.2: one exact line between the first and last keypoints, whose
  // interior keypoints then constrain nothing; or the authors' polyline.
  const bool ends_only = straight && params.straight_shape == StraightShape::line;
  auto parameter = [&](std::size_t j) {
    return ends_only ? (j + 1 == m ? 1.0 : 0.0) : static_cast<double>(j);
  };
  const char* mode = mode_shape_curve;
  if (straight) {
    shape = ends_only ? make_line(keys.points.front(), keys.points.back()) : polyline_curve(keys.points);
    mode = mode_shape_line;
    Constraint c;
    c.kind = ConstraintKind::straight;
    c.references = {ConstraintRef{ConstraintRef::Kind::stroke, stroke.id, 0.0}};
    c.target = (pca.b - pca.a).normalized();
    c.enforced = true;
    c.residual = pca.max_deviation;
    out.constraints.push_back(c);
  } else {
    const MvcResult mvc = fit_mvc_curve(keys.points, keys.tangents, keys.closed, params);
    shape = mvc.curve;
    out.stats.iterations = mvc.rounds;
    out.stats.extra["evaluations"] = mvc.evaluations;
    out.stats.extra["objective"] = mvc.objective;
    out.stats.extra["initial_objective"] = mvc.initial_objective;
  }
  NetworkCurve curve = make_network_curve(network.next_curve_id(), std::move(shape), Layer::shape, stroke.id);
  const double n_samples = static_cast<double>(samples.size() - 1);
  for (std::size_t j = 0; j < m; ++j) {
    const double t = parameter(j);
    const bool interior = j > 0 && j + 1 < m;
    if (interior && ends_only) continue;
    if (interior) curve.keypoints.push_back(Keypoint{Keypoint::Kind::other, t, keys.points[j]});
    Constraint c;
    c.kind = ConstraintKind::coincident_point;
    c.references = {
        ConstraintRef{ConstraintRef::Kind::stroke, stroke.id, keys.sample[j] / n_samples},
        ConstraintRef{ConstraintRef::Kind::curve, keys.keypoint_curve[j], keys.keypoint_t[j]}};
    c.target = keys.points[j];
    c.enforced = true;
    c.residual = (evaluate(curve.curve, t) - keys.points[j]).norm();
    out.constraints.push_back(c);
    if (!straight && keys.tangent_curve[j] != 0) {
      Constraint tc;
      tc.kind = ConstraintKind::tangent;
      tc.references = {ConstraintRef{ConstraintRef::Kind::stroke, stroke.id, keys.sample[j] / n_samples},
                       ConstraintRef{ConstraintRef::Kind::curve, keys.tangent_curve[j], 0.0}};
      tc.target = keys.tangents[j];
      tc.enforced = true;
      const Vec3 tan = tangent(curve.curve, t);
      tc.residual = std::acos(std::clamp(tan.dot(keys.tangents[j]), -1.0, 1.0));
      out.constraints.push_back(tc);
    }
  }
  out.edit.curves_added.push_back(curve);
  NodeId next_node = network.next_node_id();
  const double tolerance = scaled_threshold(node_tolerance, scale);
  for (std::size_t j = 0; j < m; ++j) {
    if (keys.closed && j + 1 == m) break;  // the seam is the first keypoint
    if (ends_only && j > 0 && j + 1 < m) continue;
    connect_point(network, keys.points[j], curve.id, parameter(j), tolerance, out.edit, next_node);
  }
  return finish(mode);
}

}  // namespace sketchlab::scaffoldsketch
