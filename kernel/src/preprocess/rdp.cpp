#include "sketchlab/preprocess/rdp.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace sketchlab {
namespace {

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double u = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + u * ab - p).norm();
}

}  // namespace

std::vector<std::size_t> rdp_indices(const std::vector<Vec3>& points, double epsilon) {
  if (!(epsilon >= 0.0) || !std::isfinite(epsilon)) {
    throw std::invalid_argument("rdp: epsilon = " + std::to_string(epsilon) +
                                "; need a finite value >= 0");
  }
  const std::size_t n = points.size();
  if (n <= 2) {
    std::vector<std::size_t> all;
    for (std::size_t i = 0; i < n; ++i) all.push_back(i);
    return all;
  }
  std::vector<bool> keep(n, false);
  keep.front() = keep.back() = true;
  // Explicit stack instead of recursion: long strokes cannot overflow it.
  std::vector<std::pair<std::size_t, std::size_t>> stack{{0, n - 1}};
  while (!stack.empty()) {
    const auto [lo, hi] = stack.back();
    stack.pop_back();
    double worst = -1.0;
    std::size_t worst_i = lo;
    for (std::size_t i = lo + 1; i < hi; ++i) {
      const double d = distance_to_segment(points[i], points[lo], points[hi]);
      if (d > worst) {
        worst = d;
        worst_i = i;
      }
    }
    if (worst > epsilon) {
      keep[worst_i] = true;
      stack.emplace_back(worst_i, hi);
      stack.emplace_back(lo, worst_i);
    }
  }
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < n; ++i) {
    if (keep[i]) out.push_back(i);
  }
  return out;
}

std::vector<Vec3> rdp_simplify(const std::vector<Vec3>& points, double epsilon) {
  std::vector<Vec3> out;
  for (std::size_t i : rdp_indices(points, epsilon)) out.push_back(points[i]);
  return out;
}

}  // namespace sketchlab
