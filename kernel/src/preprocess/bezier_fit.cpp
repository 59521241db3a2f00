#include "sketchlab/preprocess/bezier_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/polyline.hpp"
#include "sketchlab/preprocess/turns.hpp"

namespace sketchlab {
namespace {

using Segment = std::array<Vec3, 4>;

double angle_between(const Vec3& a, const Vec3& b) {
  if (a.norm() == 0.0 || b.norm() == 0.0) return 0.0;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

void check_params(const BezierFitParams& p) {
  if (!(p.tolerance > 0.0) || !std::isfinite(p.tolerance)) {
    throw std::invalid_argument("fit_poly_bezier: tolerance = " + std::to_string(p.tolerance) +
                                "; need a finite value > 0");
  }
  if (!(p.max_g1_angle > 0.0 && p.max_g1_angle <= std::numbers::pi)) {
    throw std::invalid_argument("fit_poly_bezier: max_g1_angle = " +
                                std::to_string(p.max_g1_angle) + " rad; need (0, π]");
  }
  if (!(p.corner_window > 0.0) || !std::isfinite(p.corner_window) ||
      !(p.tangent_window > 0.0) || !std::isfinite(p.tangent_window)) {
    throw std::invalid_argument("fit_poly_bezier: corner_window and tangent_window must be "
                                "finite and > 0");
  }
  if (p.max_reparameterizations < 0 || p.max_reparameterizations > 1000) {
    throw std::invalid_argument("fit_poly_bezier: max_reparameterizations must be in [0, 1000]");
  }
  if (!(p.reparameterize_below >= 1.0) || !std::isfinite(p.reparameterize_below) ||
      !(p.split_tolerance >= 0.0) || !std::isfinite(p.split_tolerance)) {
    throw std::invalid_argument(
        "fit_poly_bezier: reparameterize_below must be finite and >= 1, split_tolerance finite and >= 0");
  }
}

void check_points(const std::vector<Vec3>& points, const char* where) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) {
      throw std::invalid_argument(std::string(where) + ": point " + std::to_string(i) +
                                  " is not finite");
    }
  }
}

// Index of the first point after i (up to hi) at distance >= r from p_i;
// hi if none reaches r.
std::size_t forward_at(const std::vector<Vec3>& p, std::size_t i, std::size_t hi, double r) {
  for (std::size_t j = i + 1; j <= hi; ++j) {
    if ((p[j] - p[i]).norm() >= r) return j;
  }
  return hi;
}

std::size_t backward_at(const std::vector<Vec3>& p, std::size_t i, std::size_t lo, double r) {
  for (std::size_t j = i; j-- > lo;) {
    if ((p[j] - p[i]).norm() >= r) return j;
  }
  return lo;
}

Vec3 unit_or(const Vec3& v, const Vec3& fallback) {
  const double n = v.norm();
  return n > 0.0 ? Vec3(v / n) : fallback;
}

// Fitter state for one call: the (deduplicated) points and parameters.
class Fitter {
 public:
  Fitter(const std::vector<Vec3>& p, const BezierFitParams& params) : p_(p), prm_(params) {}

  // Unit tangent at p_lo pointing into [lo, hi] (Schneider's tHat1).
  Vec3 start_tangent(std::size_t lo, std::size_t hi) const {
    const std::size_t j = forward_at(p_, lo, hi, prm_.tangent_window);
    return unit_or(p_[j] - p_[lo], unit_or(p_[lo + 1] - p_[lo], Vec3::UnitX()));
  }
  // Unit tangent at p_hi pointing back into [lo, hi] (Schneider's tHat2).
  Vec3 end_tangent(std::size_t lo, std::size_t hi) const {
    const std::size_t j = backward_at(p_, hi, lo, prm_.tangent_window);
    return unit_or(p_[j] - p_[hi], unit_or(p_[hi - 1] - p_[hi], -Vec3::UnitX()));
  }
  // Unit tangent at an interior split i pointing backwards (tHatCenter).
  Vec3 center_tangent(std::size_t lo, std::size_t i, std::size_t hi) const {
    const std::size_t b = backward_at(p_, i, lo, 0.5 * prm_.tangent_window);
    const std::size_t f = forward_at(p_, i, hi, 0.5 * prm_.tangent_window);
    return unit_or(p_[b] - p_[f], unit_or(p_[i - 1] - p_[i + 1], end_tangent(lo, i)));
  }

  // Appends the fitted segments of [lo, hi] (G1 inside) to `out`.
  void fit_section(std::size_t lo, std::size_t hi, std::vector<Segment>& out) const {
    struct Task {
      std::size_t lo, hi;
      Vec3 t1, t2;
      double tolerance;
    };
    const double piece_tolerance = prm_.split_tolerance > 0 ? prm_.split_tolerance : prm_.tolerance;
    // Explicit stack (right pushed before left) keeps the output in order
    // without recursion depth proportional to the number of points.
    std::vector<Task> stack{{lo, hi, start_tangent(lo, hi), end_tangent(lo, hi), prm_.tolerance}};
    while (!stack.empty()) {
      const Task t = stack.back();
      stack.pop_back();
      std::size_t split = 0;
      if (fit_cubic(t.lo, t.hi, t.t1, t.t2, t.tolerance, out, split)) continue;
      const Vec3 c = center_tangent(t.lo, split, t.hi);
      stack.push_back({split, t.hi, -c, t.t2, piece_tolerance});
      stack.push_back({t.lo, split, t.t1, c, piece_tolerance});
    }
  }

 private:
  // Schneider's FitCubic for one piece: true and appends on success, else
  // false with the split index (strictly inside).
  bool fit_cubic(std::size_t lo, std::size_t hi, const Vec3& t1, const Vec3& t2, double tolerance,
                 std::vector<Segment>& out, std::size_t& split) const {
    const std::size_t n = hi - lo + 1;
    if (n == 2) {
      // Two points: tangent handles at a third of the distance (exact at
      // both data points).
      const double d = (p_[hi] - p_[lo]).norm() / 3.0;
      out.push_back({p_[lo], p_[lo] + d * t1, p_[hi] + d * t2, p_[hi]});
      return true;
    }
    std::vector<double> u = chord_length_parameters(lo, hi);
    Segment bez = generate(lo, hi, u, t1, t2);
    double err = max_error(lo, hi, bez, u, split);
    if (err <= tolerance) {
      out.push_back(bez);
      return true;
    }
    // Close enough for reparameterisation to help (Schneider: 4 × error).
    if (err <= prm_.reparameterize_below * tolerance) {
      for (int it = 0; it < prm_.max_reparameterizations; ++it) {
        reparameterize(lo, hi, bez, u);
        bez = generate(lo, hi, u, t1, t2);
        err = max_error(lo, hi, bez, u, split);
        if (err <= tolerance) {
          out.push_back(bez);
          return true;
        }
      }
    }
    return false;
  }

  std::vector<double> chord_length_parameters(std::size_t lo, std::size_t hi) const {
    std::vector<double> u(hi - lo + 1, 0.0);
    for (std::size_t i = lo + 1; i <= hi; ++i) {
      u[i - lo] = u[i - lo - 1] + (p_[i] - p_[i - 1]).norm();
    }
    const double total = u.back();
    for (double& x : u) x = total > 0.0 ? x / total : 0.0;
    u.back() = 1.0;
    return u;
  }

  // Least squares for the handle lengths alpha_1, alpha_2 along the fixed
  // tangents (Schneider's GenerateBezier), with the Wu–Barsky fallback of a
  // third of the chord when the system is singular or gives a handle <= 0.
  Segment generate(std::size_t lo, std::size_t hi, const std::vector<double>& u, const Vec3& t1,
                   const Vec3& t2) const {
    const Vec3& first = p_[lo];
    const Vec3& last = p_[hi];
    double c00 = 0.0, c01 = 0.0, c11 = 0.0, x0 = 0.0, x1 = 0.0;
    for (std::size_t i = lo; i <= hi; ++i) {
      const double s = u[i - lo], r = 1.0 - s;
      const double b0 = r * r * r, b1 = 3.0 * s * r * r, b2 = 3.0 * s * s * r, b3 = s * s * s;
      const Vec3 a1 = t1 * b1, a2 = t2 * b2;
      c00 += a1.dot(a1);
      c01 += a1.dot(a2);
      c11 += a2.dot(a2);
      const Vec3 tmp = p_[i] - (first * (b0 + b1) + last * (b2 + b3));
      x0 += a1.dot(tmp);
      x1 += a2.dot(tmp);
    }
    const double det = c00 * c11 - c01 * c01;
    double al = 0.0, ar = 0.0;
    if (std::abs(det) > 1e-12 * std::max(c00 * c11, 1e-300)) {
      al = (x0 * c11 - x1 * c01) / det;
      ar = (c00 * x1 - c01 * x0) / det;
    }
    const double seg_len = (last - first).norm();
    const double eps = 1e-6 * seg_len;
    // A handle longer than the polyline it fits throws the curve out of the
    // stroke's neighbourhood between the data points (few points leave the
    // least squares nearly free: a 3-sample stroke became a loop 0.78 m
    // away): like a handle <= 0 it gets Wu–Barsky's third of the chord, and
    // the error test then splits the piece if that does not fit.
    double polyline = 0.0;
    for (std::size_t i = lo; i < hi; ++i) polyline += (p_[i + 1] - p_[i]).norm();
    if (!(al >= eps) || !(ar >= eps) || !(al <= polyline) || !(ar <= polyline)) {
      al = ar = seg_len / 3.0;
    }
    return {first, first + al * t1, last + ar * t2, last};
  }

  // Largest |Q(u_i) - p_i| (an upper bound of the distance of p_i to the
  // curve) and where it occurs, clamped strictly inside for splitting.
  // Schneider measures the data points only; between two sparse samples (a
  // tracking jump) the cubic could then bulge far from the stroke, so the
  // curve at the middle of each interval is also measured against the chord
  // it spans, and a bad interval splits at its inner end.
  double max_error(std::size_t lo, std::size_t hi, const Segment& bez,
                   const std::vector<double>& u, std::size_t& split) const {
    double worst = 0.0;
    split = lo + (hi - lo) / 2;
    for (std::size_t i = lo + 1; i < hi; ++i) {
      const double d = (bezier_point(bez, u[i - lo]) - p_[i]).norm();
      if (d > worst) {
        worst = d;
        split = i;
      }
    }
    if (hi - lo < 2) return worst;
    for (std::size_t i = lo; i < hi; ++i) {
      const Vec3 q = bezier_point(bez, 0.5 * (u[i - lo] + u[i + 1 - lo]));
      const Vec3 ab = p_[i + 1] - p_[i];
      const double len2 = ab.squaredNorm();
      const double s = len2 > 0.0 ? std::clamp((q - p_[i]).dot(ab) / len2, 0.0, 1.0) : 0.0;
      const double d = (p_[i] + s * ab - q).norm();
      if (d > worst) {
        worst = d;
        split = i + 1 < hi ? i + 1 : i;
      }
    }
    return worst;
  }

  // One Newton step per point on (Q(u) - p)·Q'(u) = 0 (Schneider's
  // Reparameterize), kept in [0, 1].
  void reparameterize(std::size_t lo, std::size_t hi, const Segment& bez,
                      std::vector<double>& u) const {
    const Vec3 a = bez[2] - 2.0 * bez[1] + bez[0];
    const Vec3 b = bez[3] - 2.0 * bez[2] + bez[1];
    for (std::size_t i = lo + 1; i < hi; ++i) {
      double& s = u[i - lo];
      const Vec3 q = bezier_point(bez, s) - p_[i];
      const Vec3 d1 = bezier_derivative(bez, s);
      const Vec3 d2 = 6.0 * ((1.0 - s) * a + s * b);
      const double den = d1.squaredNorm() + q.dot(d2);
      if (den != 0.0 && std::isfinite(den)) s = std::clamp(s - q.dot(d1) / den, 0.0, 1.0);
    }
  }

  const std::vector<Vec3>& p_;
  const BezierFitParams& prm_;
};

// Consecutive points closer than a relative epsilon are merged.
std::vector<Vec3> dedupe(const std::vector<Vec3>& points) {
  Box3 box;
  box.setEmpty();
  for (const Vec3& p : points) box.extend(p);
  const double eps = points.empty() ? 0.0 : 1e-12 * std::max(box.diagonal().norm(), 1e-300);
  std::vector<Vec3> out;
  for (const Vec3& p : points) {
    if (out.empty() || (p - out.back()).norm() > eps) out.push_back(p);
  }
  return out;
}

}  // namespace

std::vector<std::size_t> find_corners(const std::vector<Vec3>& points,
                                      const BezierFitParams& params) {
  check_params(params);
  check_points(points, "find_corners");
  const std::size_t n = points.size();
  if (n < 3) return {};
  const double w = params.corner_window;
  std::vector<double> turn(n, 0.0);
  std::vector<std::size_t> back(n, 0), fwd(n, n - 1);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    back[i] = backward_at(points, i, 0, w);
    fwd[i] = forward_at(points, i, n - 1, w);
    const Vec3 in = points[i] - points[back[i]];
    const Vec3 out = points[fwd[i]] - points[i];
    // Corners too close to an end are hooks (hooks.hpp), not G1 breaks.
    if (in.norm() < 0.5 * w || out.norm() < 0.5 * w) continue;
    turn[i] = angle_between(in, out);
  }
  std::vector<std::size_t> corners;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (turn[i] <= params.max_g1_angle) continue;
    // Local maximum within the measuring window (ties go to the first).
    bool is_max = true;
    for (std::size_t j = back[i]; j <= fwd[i] && is_max; ++j) {
      if (j < i && turn[j] >= turn[i]) is_max = false;
      if (j > i && turn[j] > turn[i]) is_max = false;
    }
    if (is_max) corners.push_back(i);
  }
  return corners;
}

namespace {

// Fits the sections [cuts[s], cuts[s+1]] of p (deduplicated) and joins them,
// sharp between sections.
Curve fit_cut_sections(const std::vector<Vec3>& p, const std::vector<std::size_t>& cuts,
                       const BezierFitParams& params) {
  const Fitter fitter(p, params);
  std::vector<Segment> segments;
  Curve curve;
  curve.kind = CurveKind::bezier;
  curve.sharp.push_back(false);
  for (std::size_t s = 0; s + 1 < cuts.size(); ++s) {
    const std::size_t before = segments.size();
    fitter.fit_section(cuts[s], cuts[s + 1], segments);
    for (std::size_t k = before; k < segments.size(); ++k) curve.sharp.push_back(false);
    // The joint closing a section is sharp unless it is the curve's end.
    if (s + 2 < cuts.size()) curve.sharp.back() = true;
  }
  curve.control_points.push_back(segments.front()[0]);
  for (const Segment& seg : segments) {
    curve.control_points.insert(curve.control_points.end(), seg.begin() + 1, seg.end());
  }
  return curve;
}

}  // namespace

std::vector<std::size_t> find_corners_by_turns(const std::vector<Vec3>& points, double angle,
                                               std::size_t min_samples, double min_length) {
  check_points(points, "find_corners_by_turns");
  const std::size_t n = points.size();
  const std::vector<double> turn = sample_turns(points, TurnSpan::across);
  const std::vector<double> cum = cumulative_length(points);
  auto ok = [&](std::size_t a, std::size_t b) { return b - a + 1 >= min_samples && cum[b] - cum[a] > min_length; };
  std::vector<std::size_t> corners;
  std::size_t prev = 0;
  for (std::size_t i = 1; i + 1 < n;) {
    if (!(turn[i] > angle)) {
      ++i;
      continue;
    }
    std::size_t best = i;
    std::size_t j = i;
    for (; j + 1 < n && turn[j] > angle; ++j)
      if (turn[j] > turn[best]) best = j;
    if (ok(prev, best) && ok(best, n - 1)) {
      corners.push_back(best);
      prev = best;
    }
    i = j;
  }
  return corners;
}

Curve fit_poly_bezier_sections(const std::vector<std::vector<Vec3>>& sections,
                               const BezierFitParams& params) {
  check_params(params);
  if (sections.empty()) throw std::invalid_argument("fit_poly_bezier_sections: no sections");
  std::vector<Vec3> all;
  std::vector<std::size_t> cuts{0};
  for (std::size_t s = 0; s < sections.size(); ++s) {
    check_points(sections[s], "fit_poly_bezier_sections");
    const std::vector<Vec3> p = dedupe(sections[s]);
    if (p.size() < 2) {
      throw std::invalid_argument("fit_poly_bezier_sections: section " + std::to_string(s) +
                                  " has fewer than 2 distinct points");
    }
    if (s > 0 && (p.front() - all.back()).norm() > 0.0) {
      throw std::invalid_argument("fit_poly_bezier_sections: section " + std::to_string(s) +
                                  " does not start where the previous one ends");
    }
    all.insert(all.end(), p.begin() + (s > 0 ? 1 : 0), p.end());
    cuts.push_back(all.size() - 1);
  }
  return fit_cut_sections(all, cuts, params);
}

Curve fit_poly_bezier(const std::vector<Vec3>& points, const BezierFitParams& params) {
  check_params(params);
  check_points(points, "fit_poly_bezier");
  const std::vector<Vec3> p = dedupe(points);
  if (p.size() < 2) {
    throw std::invalid_argument("fit_poly_bezier: need at least 2 distinct points, got " +
                                std::to_string(p.size()));
  }
  std::vector<std::size_t> cuts{0};
  for (std::size_t c : find_corners(p, params)) cuts.push_back(c);
  cuts.push_back(p.size() - 1);
  return fit_cut_sections(p, cuts, params);
}

}  // namespace sketchlab
