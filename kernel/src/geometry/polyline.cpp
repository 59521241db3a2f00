#include "sketchlab/geometry/polyline.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sketchlab {

double polyline_length(const std::vector<Vec3>& points) {
  double len = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) len += (points[i] - points[i - 1]).norm();
  return len;
}

std::vector<double> cumulative_length(const std::vector<Vec3>& points) {
  std::vector<double> cum(points.size(), 0.0);
  for (std::size_t i = 1; i < points.size(); ++i) {
    cum[i] = cum[i - 1] + (points[i] - points[i - 1]).norm();
  }
  return cum;
}

namespace {

Vec3 point_at(const std::vector<Vec3>& points, const std::vector<double>& cum, double s) {
  if (!(s > 0.0)) return points.front();
  if (s >= cum.back()) return points.back();
  // First point whose cumulative length exceeds s; s lies on the edge before it.
  const std::size_t j =
      static_cast<std::size_t>(std::upper_bound(cum.begin(), cum.end(), s) - cum.begin());
  const std::size_t i = j - 1;
  const double len = cum[j] - cum[i];
  const double u = len > 0.0 ? (s - cum[i]) / len : 0.0;
  return points[i] + u * (points[j] - points[i]);
}

}  // namespace

std::vector<Vec3> resample_polyline(const std::vector<Vec3>& points, int n) {
  if (points.empty()) throw std::invalid_argument("resample_polyline: polyline has no points");
  if (n < 2) {
    throw std::invalid_argument("resample_polyline: n = " + std::to_string(n) + "; need n >= 2");
  }
  const auto cum = cumulative_length(points);
  std::vector<Vec3> out;
  out.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    if (i == n - 1) {
      out.push_back(points.back());
    } else {
      out.push_back(point_at(points, cum, cum.back() * static_cast<double>(i) / (n - 1)));
    }
  }
  return out;
}

Vec3 point_at_length(const std::vector<Vec3>& points, double s) {
  if (points.empty()) throw std::invalid_argument("point_at_length: polyline has no points");
  return point_at(points, cumulative_length(points), s);
}

}  // namespace sketchlab
