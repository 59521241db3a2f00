#include "short_straw.hpp"

#include <algorithm>

namespace sketchlab::justdrawit {

namespace {
constexpr int window = 3;
constexpr double median_factor = 0.95;
constexpr double line_threshold = 0.95;

bool is_line(const Points2& p, std::size_t a, std::size_t b) {
  double path = 0;
  for (std::size_t i = a; i < b; ++i) path += (p[i + 1] - p[i]).norm();
  return path <= 0 || (p[b] - p[a]).norm() / path > line_threshold;
}
}  // namespace

Corners short_straw(const Points2& stroke) {
  Corners out;
  if (stroke.size() < 2) {
    out.points = stroke;
    if (!stroke.empty()) out.index = {0};
    return out;
  }
  Vec2 lo = stroke[0], hi = stroke[0];
  for (const Vec2& p : stroke) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double spacing = (hi - lo).norm() / 40.0;
  out.points = spacing > 0 ? resample(stroke, spacing) : stroke;
  const Points2& p = out.points;
  const std::size_t n = p.size();
  out.index.push_back(0);
  if (n <= 2 * window + 1) {
    out.index.push_back(n - 1);
    return out;
  }
  std::vector<double> straw(n, std::numeric_limits<double>::infinity());
  for (std::size_t i = window; i + window < n; ++i) straw[i] = (p[i - window] - p[i + window]).norm();
  std::vector<double> sorted(straw.begin() + window, straw.end() - window);
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double t = sorted[sorted.size() / 2] * median_factor;
  for (std::size_t i = window; i + window < n; ++i) {
    if (straw[i] >= t) continue;
    double best = straw[i];
    std::size_t at = i;
    while (i + window < n && straw[i] < t) {
      if (straw[i] < best) {
        best = straw[i];
        at = i;
      }
      ++i;
    }
    out.index.push_back(at);
  }
  out.index.push_back(n - 1);
  // Post-processing: split non-line runs at their shortest straw (halfway
  // corner), then drop corners whose neighbours are collinear.
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t k = 1; k < out.index.size(); ++k) {
      const std::size_t a = out.index[k - 1], b = out.index[k];
      if (b - a < 4 || is_line(p, a, b)) continue;
      const std::size_t q = (b - a) / 4;
      std::size_t at = 0;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t i = a + q; i <= b - q; ++i)
        if (straw[i] < best) {
          best = straw[i];
          at = i;
        }
      if (at > a && at < b && std::isfinite(best)) {
        out.index.insert(out.index.begin() + static_cast<std::ptrdiff_t>(k), at);
        changed = true;
        break;
      }
    }
  }
  for (std::size_t k = 1; k + 1 < out.index.size();) {
    if (is_line(p, out.index[k - 1], out.index[k + 1]))
      out.index.erase(out.index.begin() + static_cast<std::ptrdiff_t>(k));
    else
      ++k;
  }
  return out;
}

}  // namespace sketchlab::justdrawit
