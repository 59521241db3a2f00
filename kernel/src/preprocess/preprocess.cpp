#include "sketchlab/preprocess/preprocess.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sketchlab/geometry/polyline.hpp"
#include "sketchlab/preprocess/bezier_fit.hpp"
#include "sketchlab/preprocess/input_filter.hpp"
#include "sketchlab/preprocess/line_detection.hpp"
#include "sketchlab/preprocess/rdp.hpp"

namespace sketchlab {
namespace {

std::string range_error(const char* name, double value, const char* allowed) {
  std::ostringstream s;
  s << name << " = " << value << ": allowed " << allowed;
  return s.str();
}

// Item 1 as CASSIE's structuring shows it (app_trim_last_end): the kept
// points `pts` (times `ts`, input sample `index` of each) end `trim` seconds
// of hand motion before the last of them, at the hand's mean speed over the
// input's last kEndSpeedWindow seconds, measured back along the input
// (`points`, `times`); the kept points beyond are dropped and the end's index
// is the input sample before it. A mean speed rather than the time of each
// sample: a desktop viewer stamps coalesced input events with one time, which
// would put all of a burst's motion in no time at the end. Unchanged when the
// input gives no speed or the stroke is shorter than the cut.
constexpr double kEndSpeedWindow = 0.1;  // s: 9 frames at 90 Hz
void trim_last_end(const std::vector<Vec3>& points, const std::vector<double>& times, double trim,
                   std::vector<Vec3>& pts, std::vector<double>& ts, std::vector<std::size_t>& index) {
  if (!(trim > 0.0)) return;
  const std::size_t first = index.front(), last = index.back();
  // Arclength along the input from `first`: s[i - first] at input sample i.
  const std::vector<double> s =
      cumulative_length(std::vector<Vec3>(points.begin() + first, points.begin() + last + 1));
  std::size_t from = last;
  while (from > first && times[last] - times[from] < kEndSpeedWindow) --from;
  const double span = times[last] - times[from], moved = s.back() - s[from - first];
  if (!(span > 0.0) || !(moved > 0.0)) return;
  const double at = s.back() - moved / span * trim;  // the new end's arclength
  if (!(at > 0.0)) return;
  // The end lies on the input segment [j - 1, j]: s at j - 1 <= at < s at j.
  const std::size_t j = first + static_cast<std::size_t>(std::upper_bound(s.begin(), s.end(), at) - s.begin());
  const double u = (at - s[j - 1 - first]) / (s[j - first] - s[j - 1 - first]);
  const Vec3 end = points[j - 1] + u * (points[j] - points[j - 1]);
  const double t = times[j - 1] + u * (times[j] - times[j - 1]);
  while (index.back() >= j) {
    pts.pop_back();
    ts.pop_back();
    index.pop_back();
  }
  if (end == pts.back()) return;  // the cut ends on a kept sample
  pts.push_back(end);
  ts.push_back(t);
  index.push_back(j - 1);
}

// The CASSIE app's pipeline (reference items 1–4); d = δ/s.
Preprocessed preprocess_app(const std::vector<Vec3>& points, const std::vector<double>& times,
                            const PreprocessParams& params, double d) {
  InputFilterParams ip;
  ip.min_step = params.app_sample_step_factor * d;
  ip.min_length = params.app_min_length_factor * d;
  ip.min_duration = params.app_min_duration;
  ip.end_trim = params.app_end_trim;
  if (!params.app_filter_input) ip = {0.0, 0.0, 0.0, 0.0};
  const FilteredInput in = filter_input(points, times, ip);
  if (in.dropped) {
    throw std::invalid_argument("preprocess_stroke: dropped as the CASSIE app does: " + in.reason);
  }
  std::vector<Vec3> pts;
  std::vector<double> ts;
  std::vector<std::size_t> index = in.indices;
  for (std::size_t i : index) {
    pts.push_back(points[i]);
    if (!times.empty()) ts.push_back(times[i]);
  }
  if (params.app_trim_last_end && ts.size() >= 2) trim_last_end(points, times, params.app_end_trim, pts, ts, index);
  Preprocessed out;
  out.kept = {index.front(), index.back()};
  // Item 2: the line test comes first, on the filtered samples, hooks
  // included; the app compares the excess ratio with δ(s) itself.
  if (params.detect_lines && detect_line_by_excess(pts, ts, d, d / params.app_line_time, d).is_line) {
    out.is_line = true;
    out.points = pts;
    out.curve = make_line(pts.front(), pts.back());
    return out;
  }
  IndexRange r{0, pts.size() - 1};
  if (params.remove_hooks) {
    TurnHookParams hp;
    hp.max_length = params.hook_max_length_factor * d;
    hp.max_fraction = params.hook_max_fraction;
    hp.min_angle = params.app_hook_angle;
    hp.span = params.app_hook_turn;
    r = find_hookless_range_by_turns(pts, hp);
    out.hook_cut = {r.first > 0, r.last + 1 < pts.size()};
  }
  out.kept = {index[r.first], index[r.last]};
  out.points.assign(pts.begin() + static_cast<std::ptrdiff_t>(r.first),
                    pts.begin() + static_cast<std::ptrdiff_t>(r.last) + 1);
  // Item 4: corners on the raw samples, then RDP and Schneider per section.
  std::vector<std::size_t> cuts{0};
  for (std::size_t c : find_corners_by_turns(out.points, params.max_g1_angle,
                                             static_cast<std::size_t>(params.app_corner_min_samples),
                                             params.app_corner_min_length_factor * d))
    cuts.push_back(c);
  cuts.push_back(out.points.size() - 1);
  std::vector<std::vector<Vec3>> sections;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const std::vector<Vec3> piece(out.points.begin() + static_cast<std::ptrdiff_t>(cuts[k]),
                                  out.points.begin() + static_cast<std::ptrdiff_t>(cuts[k + 1]) + 1);
    sections.push_back(rdp_simplify(piece, params.rdp_epsilon_factor * d));
  }
  BezierFitParams fp;
  fp.tolerance = params.fit_error_factor * d;
  fp.max_g1_angle = params.max_g1_angle;
  fp.corner_window = d;
  fp.tangent_window = 1e-9 * d;  // Schneider's tangents: the first (last) two points
  fp.max_reparameterizations = params.app_reparameterizations;
  fp.reparameterize_below = params.app_reparameterize_below;
  fp.split_tolerance = params.app_split_tolerance;
  out.curve = fit_poly_bezier_sections(sections, fp);
  return out;
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
  auto finite_nonneg = [](double x) { return std::isfinite(x) && x >= 0.0; };
  if (!finite_nonneg(p.app_sample_step_factor)) return range_error("app_sample_step_factor", p.app_sample_step_factor, ">= 0 (×δ)");
  if (!finite_nonneg(p.app_min_length_factor)) return range_error("app_min_length_factor", p.app_min_length_factor, ">= 0 (×δ)");
  if (!finite_nonneg(p.app_min_duration)) return range_error("app_min_duration", p.app_min_duration, ">= 0 s");
  if (!finite_nonneg(p.app_end_trim)) return range_error("app_end_trim", p.app_end_trim, ">= 0 s");
  if (!finite_pos(p.app_line_time)) return range_error("app_line_time", p.app_line_time, "> 0 s");
  if (!(p.app_hook_angle > 0.0 && p.app_hook_angle < std::numbers::pi)) {
    return range_error("app_hook_angle", p.app_hook_angle, "(0, π) rad");
  }
  if (p.app_corner_min_samples < 2) return range_error("app_corner_min_samples", p.app_corner_min_samples, ">= 2");
  if (!finite_nonneg(p.app_corner_min_length_factor)) {
    return range_error("app_corner_min_length_factor", p.app_corner_min_length_factor, ">= 0 (×δ)");
  }
  if (p.app_reparameterizations < 0 || p.app_reparameterizations > 1000) {
    return range_error("app_reparameterizations", p.app_reparameterizations, "[0, 1000]");
  }
  if (!(p.app_reparameterize_below >= 1.0) || !std::isfinite(p.app_reparameterize_below)) {
    return range_error("app_reparameterize_below", p.app_reparameterize_below, ">= 1");
  }
  if (!finite_nonneg(p.app_split_tolerance)) return range_error("app_split_tolerance", p.app_split_tolerance, ">= 0 m");
  return {};
}

PreprocessParams cassie_app_preprocess() {
  PreprocessParams p;
  p.rules = PreprocessRules::cassie_app;
  return p;
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
  if (params.rules == PreprocessRules::cassie_app) return preprocess_app(points, times, params, d);
  Preprocessed out;
  out.kept = {0, points.size() - 1};
  if (params.remove_hooks) {
    HookParams hp;
    hp.max_length = params.hook_max_length_factor * d;
    hp.min_length = params.hook_min_length_factor * d;
    hp.max_fraction = params.hook_max_fraction;
    hp.min_angle = params.hook_min_angle;
    out.kept = find_hookless_range(points, hp);
    out.hook_cut = {out.kept.first > 0, out.kept.last + 1 < points.size()};
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
