#include "sketchlab/preprocess/hooks.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sketchlab/geometry/polyline.hpp"
#include "sketchlab/preprocess/turns.hpp"

namespace sketchlab {
namespace {

double angle_between(const Vec3& a, const Vec3& b) {
  const double na = a.norm(), nb = b.norm();
  if (na == 0.0 || nb == 0.0) return 0.0;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// Least-squares direction of p[lo..hi] (principal axis), oriented from p_lo
// to p_hi. Averaging over all points of a piece keeps sampling jitter from
// masquerading as a turn, which chords between two noisy samples do not.
Vec3 fit_direction(const std::vector<Vec3>& p, std::size_t lo, std::size_t hi) {
  const Vec3 chord = p[hi] - p[lo];
  if (hi - lo < 2) return chord;
  Vec3 mean = Vec3::Zero();
  for (std::size_t i = lo; i <= hi; ++i) mean += p[i];
  mean /= static_cast<double>(hi - lo + 1);
  Mat3 cov = Mat3::Zero();
  for (std::size_t i = lo; i <= hi; ++i) cov += (p[i] - mean) * (p[i] - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(cov);
  const Vec3 axis = eig.eigenvectors().col(2);
  return axis.dot(chord) < 0.0 ? Vec3(-axis) : axis;
}

// First index j in (i, n) with |p_j - p_i| >= r, or n if none.
std::size_t forward_at(const std::vector<Vec3>& p, std::size_t i, double r) {
  for (std::size_t j = i + 1; j < p.size(); ++j) {
    if ((p[j] - p[i]).norm() >= r) return j;
  }
  return p.size();
}

// Last index j in [0, i) with |p_j - p_i| >= r, or n if none.
std::size_t backward_at(const std::vector<Vec3>& p, std::size_t i, double r) {
  for (std::size_t j = i; j-- > 0;) {
    if ((p[j] - p[i]).norm() >= r) return j;
  }
  return p.size();
}

// Cut index (kept point) of a hook at the start of p, or 0 if none.
std::size_t start_hook(const std::vector<Vec3>& p, const HookParams& hp) {
  const std::size_t n = p.size();
  const auto cum = cumulative_length(p);
  const double max_arc = hp.max_fraction * cum.back();
  double best_turn = -1.0;
  std::size_t best = 0;
  for (std::size_t i = 1; i + 1 < n && cum[i] <= max_arc; ++i) {
    const Vec3 hook = p[i] - p[0];
    const double a = hook.norm();
    if (a < hp.min_length) continue;
    if (a > hp.max_length) break;
    const std::size_t f = forward_at(p, i, a);
    if (f == n) break;
    const double turn = angle_between(fit_direction(p, 0, i), fit_direction(p, i, f));
    if (turn < hp.min_angle || turn <= best_turn) continue;
    // A C1 discontinuity turns as much at half the scale; a smooth bend
    // turns about half as much.
    const std::size_t fh = forward_at(p, i, 0.5 * a);
    const std::size_t bh = backward_at(p, i, 0.5 * a);
    if (fh == n || bh == n) continue;
    if (angle_between(fit_direction(p, bh, i), fit_direction(p, i, fh)) < hp.min_angle) continue;
    if (std::isfinite(hp.max_bend_ratio) && a >= 2.0 * hp.min_length) {
      std::size_t m = 1;
      while (m < i && (p[m] - p[0]).norm() < 0.5 * a) ++m;
      if (m < i && angle_between(fit_direction(p, 0, m), fit_direction(p, m, i)) > hp.max_bend_ratio * turn)
        continue;
    }
    best_turn = turn;
    best = i;
  }
  return best;
}

// Throws std::invalid_argument naming `fn` unless `points` holds at least 2
// finite points.
void require_finite_points(const std::vector<Vec3>& points, const char* fn) {
  if (points.size() < 2)
    throw std::invalid_argument(std::string(fn) + ": need at least 2 points, got " + std::to_string(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite())
      throw std::invalid_argument(std::string(fn) + ": point " + std::to_string(i) + " is not finite");
}

}  // namespace

IndexRange find_hookless_range(const std::vector<Vec3>& points, const HookParams& params) {
  require_finite_points(points, "find_hookless_range");
  const std::size_t n = points.size();
  if (!(params.max_length > 0.0) || !std::isfinite(params.max_length) ||
      !(params.min_length >= 0.0) || !(params.min_length <= params.max_length) ||
      !(params.max_fraction >= 0.0 && params.max_fraction < 0.5) ||
      !(params.min_angle > 0.0 && params.min_angle < 3.14159265358979) ||
      !(params.max_bend_ratio >= 0.0)) {
    throw std::invalid_argument(
        "find_hookless_range: need 0 <= min_length <= max_length (finite, > 0), "
        "max_fraction in [0, 0.5), min_angle in (0, π), max_bend_ratio >= 0");
  }
  IndexRange r{0, n - 1};
  r.first = start_hook(points, params);
  std::vector<Vec3> rest(points.rbegin(), points.rend() - static_cast<std::ptrdiff_t>(r.first));
  if (rest.size() >= 2) r.last = n - 1 - start_hook(rest, params);
  return r;
}

IndexRange find_hookless_range_by_turns(const std::vector<Vec3>& points, const TurnHookParams& params) {
  require_finite_points(points, "find_hookless_range_by_turns");
  const std::size_t n = points.size();
  if (!(params.max_length > 0.0) || !std::isfinite(params.max_length) ||
      !(params.max_fraction >= 0.0 && params.max_fraction < 0.5) ||
      !(params.min_angle > 0.0 && params.min_angle < std::numbers::pi)) {
    throw std::invalid_argument(
        "find_hookless_range_by_turns: need max_length > 0 (finite), max_fraction in [0, 0.5), "
        "min_angle in (0, π)");
  }
  const std::vector<double> turn = sample_turns(points, params.span);
  const double limit = std::min(params.max_length, params.max_fraction * polyline_length(points));
  IndexRange r{0, n - 1};
  double scanned = 0.0;
  std::size_t cut = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    scanned += (points[i] - points[i - 1]).norm();
    if (scanned >= limit) break;
    if (turn[i] > params.min_angle) cut = i;
  }
  if (cut > 0 && n - cut >= params.min_remaining) r.first = cut;
  scanned = 0.0;
  cut = 0;
  for (std::size_t j = n - 1; j-- > r.first + 1;) {
    scanned += (points[j + 1] - points[j]).norm();
    if (scanned >= limit) break;
    if (turn[j] > params.min_angle) cut = j;
  }
  if (cut > 0 && cut - r.first + 1 >= params.min_remaining) r.last = cut;
  return r;
}

}  // namespace sketchlab
