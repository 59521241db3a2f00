#include "sketchlab/preprocess/line_detection.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "sketchlab/geometry/polyline.hpp"

namespace sketchlab {
namespace {

void check_points(const std::vector<Vec3>& points, const char* where) {
  if (points.size() < 2) {
    throw std::invalid_argument(std::string(where) + ": need at least 2 points, got " +
                                std::to_string(points.size()));
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) {
      throw std::invalid_argument(std::string(where) + ": point " + std::to_string(i) +
                                  " is not finite");
    }
  }
}

void check_times(const std::vector<Vec3>& points, const std::vector<double>& times, const char* where) {
  if (!times.empty() && times.size() != points.size()) {
    throw std::invalid_argument(std::string(where) + ": " + std::to_string(times.size()) +
                                " times for " + std::to_string(points.size()) + " points");
  }
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!std::isfinite(times[i])) {
      throw std::invalid_argument(std::string(where) + ": time " + std::to_string(i) + " is not finite");
    }
    if (i > 0 && times[i] < times[i - 1]) {
      throw std::invalid_argument(std::string(where) + ": time " + std::to_string(i) +
                                  " is earlier than the previous sample");
    }
  }
}

double mean_speed(double length, const std::vector<double>& times) {
  const double duration = times.empty() ? 0.0 : times.back() - times.front();
  return duration > 0.0 ? length / duration : std::numeric_limits<double>::infinity();
}

// Polyline through the stroke ends and the centroids of consecutive pieces
// of about `spacing` arclength. Centroids average the sampling jitter that
// would otherwise inflate the length of even a perfectly straight stroke.
std::vector<Vec3> coarse_polyline(const std::vector<Vec3>& points, double spacing) {
  const auto cum = cumulative_length(points);
  std::vector<Vec3> out{points.front()};
  Vec3 sum = Vec3::Zero();
  int count = 0;
  double piece_end = spacing;
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    if (cum[i] > piece_end && count > 0) {
      out.push_back(sum / count);
      sum.setZero();
      count = 0;
      while (piece_end < cum[i]) piece_end += spacing;
    }
    sum += points[i];
    ++count;
  }
  if (count > 0) out.push_back(sum / count);
  out.push_back(points.back());
  return out;
}

}  // namespace

LineDetection detect_line(const std::vector<Vec3>& points, const std::vector<double>& times,
                          const LineDetectionParams& params) {
  check_points(points, "detect_line");
  if (!(params.min_length_ratio > 0.0 && params.min_length_ratio <= 1.0) ||
      !(params.min_speed >= 0.0) || !std::isfinite(params.min_speed) ||
      !(params.resample_spacing > 0.0) || !std::isfinite(params.resample_spacing)) {
    throw std::invalid_argument(
        "detect_line: need min_length_ratio in (0, 1], finite min_speed >= 0, "
        "finite resample_spacing > 0");
  }
  check_times(points, times, "detect_line");
  LineDetection r;
  const std::vector<Vec3> coarse = coarse_polyline(points, params.resample_spacing);
  r.length = polyline_length(coarse);
  if (!(r.length > 0.0)) throw std::invalid_argument("detect_line: stroke has zero length");
  const double chord = (points.back() - points.front()).norm();
  r.length_ratio = std::min(1.0, chord / r.length);
  r.mean_speed = mean_speed(r.length, times);
  r.is_line = r.length_ratio >= params.min_length_ratio && r.mean_speed >= params.min_speed;
  return r;
}

LineDetection detect_line_by_excess(const std::vector<Vec3>& points,
                                    const std::vector<double>& times, double max_excess,
                                    double min_speed, double min_length) {
  check_points(points, "detect_line_by_excess");
  check_times(points, times, "detect_line_by_excess");
  if (!(max_excess >= 0.0) || !(min_speed >= 0.0) || !(min_length >= 0.0) || !std::isfinite(max_excess) ||
      !std::isfinite(min_speed) || !std::isfinite(min_length)) {
    throw std::invalid_argument(
        "detect_line_by_excess: max_excess, min_speed and min_length must be finite and >= 0");
  }
  LineDetection r;
  r.length = polyline_length(points);
  if (!(r.length > 0.0)) throw std::invalid_argument("detect_line_by_excess: stroke has zero length");
  const double chord = (points.back() - points.front()).norm();
  r.length_ratio = std::min(1.0, chord / r.length);
  r.mean_speed = mean_speed(r.length, times);
  r.is_line = r.length < min_length ||
              (chord > 0.0 && (r.length - chord) / chord < max_excess && r.mean_speed > min_speed);
  return r;
}

PcaLine fit_pca_line(const std::vector<Vec3>& points, double max_deviation_ratio,
                     double length_tolerance) {
  check_points(points, "fit_pca_line");
  if (!(max_deviation_ratio >= 0.0) || !(length_tolerance >= 0.0 && length_tolerance < 1.0)) {
    throw std::invalid_argument(
        "fit_pca_line: need max_deviation_ratio >= 0 and length_tolerance in [0, 1)");
  }
  const double n = static_cast<double>(points.size());
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points) mean += p;
  mean /= n;
  Mat3 cov = Mat3::Zero();
  for (const Vec3& p : points) cov += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(cov);
  Vec3 axis = eig.eigenvectors().col(2);  // largest eigenvalue last
  if ((points.back() - points.front()).dot(axis) < 0.0) axis = -axis;
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  PcaLine r;
  for (const Vec3& p : points) {
    const double s = (p - mean).dot(axis);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
    r.max_deviation = std::max(r.max_deviation, (p - mean - s * axis).norm());
  }
  r.a = mean + lo * axis;
  r.b = mean + hi * axis;
  const double seg = hi - lo;
  const double len = polyline_length(points);
  if (!(len > 0.0)) throw std::invalid_argument("fit_pca_line: stroke has zero length");
  r.is_line = r.max_deviation <= max_deviation_ratio * seg && seg >= (1.0 - length_tolerance) * len;
  return r;
}

}  // namespace sketchlab
