#include "sketchlab/preprocess/preprocess.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sketchlab/preprocess/bezier_fit.hpp"
#include "sketchlab/preprocess/line_detection.hpp"
#include "sketchlab/preprocess/rdp.hpp"

namespace sketchlab {
namespace {

std::string range_error(const char* name, double value, const char* allowed) {
  std::ostringstream s;
  s << name << " = " << value << ": allowed " << allowed;
  return s.str();
}

}  // namespace

std::string validate(const PreprocessParams& p) {
  auto finite_pos = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (!finite_pos(p.delta)) return range_error("delta", p.delta, "> 0 m");
  if (!finite_pos(p.fit_error_factor)) return range_error("fit_error_factor", p.fit_error_factor, "> 0 (×δ)");
  if (!(p.max_g1_angle > 0.0 && p.max_g1_angle <= std::numbers::pi)) {
    return range_error("max_g1_angle", p.max_g1_angle, "(0, π] rad");
  }
  if (!finite_pos(p.hook_max_length_factor)) {
    return range_error("hook_max_length_factor", p.hook_max_length_factor, "> 0 (×δ)");
  }
  if (!(p.hook_max_fraction >= 0.0 && p.hook_max_fraction < 0.5)) {
    return range_error("hook_max_fraction", p.hook_max_fraction, "[0, 0.5)");
  }
  if (!(p.hook_min_length_factor >= 0.0 && p.hook_min_length_factor <= p.hook_max_length_factor)) {
    return range_error("hook_min_length_factor", p.hook_min_length_factor,
                       "[0, hook_max_length_factor] (×δ)");
  }
  if (!(p.hook_min_angle > 0.0 && p.hook_min_angle < std::numbers::pi)) {
    return range_error("hook_min_angle", p.hook_min_angle, "(0, π) rad");
  }
  if (!(p.line_min_length_ratio > 0.0 && p.line_min_length_ratio <= 1.0)) {
    return range_error("line_min_length_ratio", p.line_min_length_ratio, "(0, 1]");
  }
  if (!(p.line_min_speed >= 0.0) || !std::isfinite(p.line_min_speed)) {
    return range_error("line_min_speed", p.line_min_speed, ">= 0 m/s");
  }
  if (!(p.rdp_epsilon_factor >= 0.0) || !std::isfinite(p.rdp_epsilon_factor)) {
    return range_error("rdp_epsilon_factor", p.rdp_epsilon_factor, ">= 0 (×δ)");
  }
  if (!finite_pos(p.corner_window_factor)) {
    return range_error("corner_window_factor", p.corner_window_factor, "> 0 (×δ)");
  }
  if (!finite_pos(p.tangent_window_factor)) {
    return range_error("tangent_window_factor", p.tangent_window_factor, "> 0 (×δ)");
  }
  return {};
}

Preprocessed preprocess_stroke(const std::vector<Vec3>& points, const std::vector<double>& times,
                               const PreprocessParams& params, double workspace_scale) {
  if (const std::string e = validate(params); !e.empty()) {
    throw std::invalid_argument("preprocess_stroke: " + e);
  }
  if (!(workspace_scale > 0.0) || !std::isfinite(workspace_scale)) {
    throw std::invalid_argument("preprocess_stroke: workspace_scale = " +
                                std::to_string(workspace_scale) + "; need a finite value > 0");
  }
  if (points.size() < 2) {
    throw std::invalid_argument("preprocess_stroke: stroke has " + std::to_string(points.size()) +
                                " point(s); need at least 2 distinct points");
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) {
      throw std::invalid_argument("preprocess_stroke: point " + std::to_string(i) +
                                  " is not finite");
    }
  }
  if (!times.empty() && times.size() != points.size()) {
    throw std::invalid_argument("preprocess_stroke: " + std::to_string(times.size()) +
                                " times for " + std::to_string(points.size()) + " points");
  }
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!std::isfinite(times[i]) || (i > 0 && times[i] < times[i - 1])) {
      throw std::invalid_argument("preprocess_stroke: time " + std::to_string(i) +
                                  " is not finite or earlier than the previous sample");
    }
  }
  bool distinct = false;
  for (const Vec3& p : points) distinct = distinct || p != points.front();
  if (!distinct) {
    throw std::invalid_argument(
        "preprocess_stroke: stroke has zero length (all points coincide); need at least 2 "
        "distinct points");
  }

  // δ(s) = δ/s: thresholds are physical sizes at the user's hand.
  const double d = params.delta / workspace_scale;
  Preprocessed out;
  out.kept = {0, points.size() - 1};
  if (params.remove_hooks) {
    HookParams hp;
    hp.max_length = params.hook_max_length_factor * d;
    hp.min_length = params.hook_min_length_factor * d;
    hp.max_fraction = params.hook_max_fraction;
    hp.min_angle = params.hook_min_angle;
    out.kept = find_hookless_range(points, hp);
  }
  out.points.assign(points.begin() + static_cast<std::ptrdiff_t>(out.kept.first),
                    points.begin() + static_cast<std::ptrdiff_t>(out.kept.last) + 1);
  std::vector<double> kept_times;
  if (!times.empty()) {
    kept_times.assign(times.begin() + static_cast<std::ptrdiff_t>(out.kept.first),
                      times.begin() + static_cast<std::ptrdiff_t>(out.kept.last) + 1);
  }

  if (params.detect_lines) {
    LineDetectionParams lp;
    lp.min_length_ratio = params.line_min_length_ratio;
    lp.min_speed = params.line_min_speed / workspace_scale;
    lp.resample_spacing = d;
    out.is_line = detect_line(out.points, kept_times, lp).is_line;
  }
  if (out.is_line) {
    out.curve = make_line(out.points.front(), out.points.back());
    return out;
  }
  BezierFitParams fp;
  fp.tolerance = params.fit_error_factor * d;
  fp.max_g1_angle = params.max_g1_angle;
  fp.corner_window = params.corner_window_factor * d;
  fp.tangent_window = params.tangent_window_factor * d;
  out.curve = fit_poly_bezier(rdp_simplify(out.points, params.rdp_epsilon_factor * d), fp);
  return out;
}

Preprocessed preprocess_stroke(const Stroke& stroke, const PreprocessParams& params) {
  std::vector<Vec3> pts;
  std::vector<double> times;
  pts.reserve(stroke.samples.size());
  times.reserve(stroke.samples.size());
  for (const Sample& s : stroke.samples) {
    pts.push_back(s.position);
    times.push_back(s.time);
  }
  try {
    return preprocess_stroke(pts, times, params, stroke.workspace_scale);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("stroke " + std::to_string(stroke.id) + ": " + e.what());
  }
}

}  // namespace sketchlab
