#include "sketchlab/preprocess/input_filter.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "sketchlab/geometry/polyline.hpp"

namespace sketchlab {

FilteredInput filter_input(const std::vector<Vec3>& points, const std::vector<double>& times,
                           const InputFilterParams& p) {
  if (!times.empty() && times.size() != points.size()) {
    throw std::invalid_argument("filter_input: " + std::to_string(times.size()) + " times for " +
                                std::to_string(points.size()) + " points");
  }
  if (!(p.min_step >= 0) || !(p.min_length >= 0) || !(p.min_duration >= 0) || !(p.end_trim >= 0)) {
    throw std::invalid_argument("filter_input: min_step, min_length, min_duration and end_trim must be >= 0");
  }
  FilteredInput out;
  if (points.empty()) {
    out.dropped = true;
    out.reason = "no samples";
    return out;
  }
  // UpdateStroke: a new sample only when the hand moved more than min_step.
  std::vector<std::size_t> moved{0};
  for (std::size_t i = 1; i < points.size(); ++i)
    if ((points[i] - points[moved.back()]).norm() > p.min_step) moved.push_back(i);
  std::vector<Vec3> taken;
  for (std::size_t i : moved) taken.push_back(points[i]);
  const double length = polyline_length(taken);
  const double ends = (taken.back() - taken.front()).norm();
  const double duration = times.empty() ? 0.0 : times[moved.back()] - times[moved.front()];
  std::ostringstream why;
  if (length < p.min_length) {
    why << "length " << length << " below " << p.min_length;
  } else if (!times.empty() && duration < p.min_duration && ends < p.min_length) {
    why << "lasts " << duration << " s (< " << p.min_duration << " s) with ends " << ends
        << " apart (< " << p.min_length << ")";
  }
  if (!why.str().empty()) {
    out.dropped = true;
    out.reason = why.str();
    out.indices = moved;
    return out;
  }
  // GetSafePoints: drop the samples of the first and last end_trim seconds,
  // keeping the two end samples.
  if (times.empty() || moved.size() <= 2) {
    out.indices = moved;
    return out;
  }
  const double t0 = times[moved.front()], t1 = times[moved.back()];
  out.indices.push_back(moved.front());
  for (std::size_t k = 1; k + 1 < moved.size(); ++k) {
    const double t = times[moved[k]];
    if (t >= t0 + p.end_trim && t <= t1 - p.end_trim) out.indices.push_back(moved[k]);
  }
  out.indices.push_back(moved.back());
  return out;
}

}  // namespace sketchlab
