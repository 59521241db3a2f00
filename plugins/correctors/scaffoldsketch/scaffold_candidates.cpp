#include "scaffold_candidates.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab::scaffoldsketch {
namespace {

constexpr double min_length = 1e-12;  // m: below this l has no direction

Vec3 line_point(LinePoint at, const Vec3& a, const Vec3& b) {
  switch (at) {
    case LinePoint::start: return a;
    case LinePoint::end: return b;
    case LinePoint::middle: return 0.5 * (a + b);
  }
  return a;
}

// d(line point)/d(a, b) as the two 3x3 blocks' scalar factors.
std::pair<double, double> line_point_factors(LinePoint at) {
  switch (at) {
    case LinePoint::start: return {1.0, 0.0};
    case LinePoint::end: return {0.0, 1.0};
    case LinePoint::middle: return {0.5, 0.5};
  }
  return {1.0, 0.0};
}

Mat3 cross_matrix(const Vec3& v) {
  Mat3 m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

}  // namespace

bool is_scaffold_line(const NetworkCurve& curve) {
  // §3.2: a line drawn in scaffold or guide mode, or in no mode (automatic,
  // free: this corrector makes those scaffold lines too, e.g. the reference
  // curves of imported CASSIE sessions); a straight shape curve is not one.
  return curve.layer != Layer::shape && curve.curve.kind == CurveKind::line &&
         curve.curve.control_points.size() == 4;
}

int term_linearisation(const ScaffoldTerm& term, const Vec3& a, const Vec3& b, Vec3& r, Mat3& m,
                       double& fa, double& fb) {
  m.setZero();
  r.setZero();
  const Vec3 v = b - a;
  const double length = v.norm();
  switch (term.kind) {
    case TermKind::point_point: {  // eq. 1: r = l_i - p
      std::tie(fa, fb) = line_point_factors(term.at);
      r = line_point(term.at, a, b) - term.p;
      m = Mat3::Identity();
      return 3;
    }
    case TermKind::point_line: {  // eq. 2: r = (k_a - k_b) x (k_a - l_i) / |k_a - k_b|
      const Vec3 e = term.ka - term.kb;
      const double n = e.norm();
      std::tie(fa, fb) = line_point_factors(term.at);
      if (n < min_length) {  // degenerate k: fall back to the point distance
        r = line_point(term.at, a, b) - term.ka;
        m = Mat3::Identity();
        return 3;
      }
      r = e.cross(term.ka - line_point(term.at, a, b)) / n;
      m = -cross_matrix(e) / n;  // d r / d l_i
      return 3;
    }
    case TermKind::perpendicular:
    case TermKind::parallel: {
      fa = -1.0;  // functions of b - a
      fb = 1.0;
      if (length < min_length) {
        r.x() = 1.0;
        return 1;
      }
      const Vec3 u = v / length;
      const double c = u.dot(term.d);
      // d(u·d)/db = dᵀ(I - u uᵀ)/|v|, and the negative for a.
      const Vec3 g = (term.d - c * u) / length;
      if (term.kind == TermKind::perpendicular) {  // eq. 3: r = u·d
        r.x() = c;
        m.row(0) = g.transpose();
        return 1;
      }
      // Parallel as |u x d| = sin θ (same zero set and inclusion angle as
      // eq. 4's (1 - |u·d|)², whose θ⁴ well is too flat to tell a satisfied
      // constraint from a compromise; see README).
      r = u.cross(term.d);
      const Mat3 p = (Mat3::Identity() - u * u.transpose()) / length;
      m = -cross_matrix(term.d) * p;  // d(u x d)/db
      return 3;
    }
    case TermKind::equal_length: {  // eq. 5: r = |l_a - l_b| / |k_a - k_b| - 1
      fa = -1.0;
      fb = 1.0;
      const double k = std::max((term.ka - term.kb).norm(), min_length);
      r.x() = length / k - 1.0;
      if (length >= min_length) m.row(0) = (v / length).transpose() / k;
      return 1;
    }
  }
  fa = fb = 0.0;
  return 0;
}

int term_residual(const ScaffoldTerm& term, const Vec3& a, const Vec3& b, Vec3& r,
                  Eigen::Matrix<double, 3, 6>& jacobian) {
  Mat3 m;
  double fa = 0, fb = 0;
  const int rows = term_linearisation(term, a, b, r, m, fa, fb);
  jacobian.block<3, 3>(0, 0) = fa * m;
  jacobian.block<3, 3>(0, 3) = fb * m;
  return rows;
}

double term_energy(const ScaffoldTerm& term, const Vec3& a, const Vec3& b) {
  // The squared residual of term_residual without its Jacobian: the line
  // search of the solver evaluates this far more often than the Jacobians.
  switch (term.kind) {
    case TermKind::point_point: return (line_point(term.at, a, b) - term.p).squaredNorm();
    case TermKind::point_line: {
      const Vec3 e = term.ka - term.kb;
      const double n2 = e.squaredNorm();
      const Vec3 x = line_point(term.at, a, b);
      if (n2 < min_length * min_length) return (x - term.ka).squaredNorm();
      return e.cross(term.ka - x).squaredNorm() / n2;
    }
    case TermKind::perpendicular:
    case TermKind::parallel: {
      const Vec3 v = b - a;
      const double length = v.norm();
      if (length < min_length) return 1.0;
      if (term.kind == TermKind::perpendicular) {
        const double c = v.dot(term.d) / length;
        return c * c;
      }
      return v.cross(term.d).squaredNorm() / (length * length);
    }
    case TermKind::equal_length: {
      const double k = std::max((term.ka - term.kb).norm(), min_length);
      const double r = (b - a).norm() / k - 1.0;
      return r * r;
    }
  }
  return 0.0;
}

bool same_energy(const ScaffoldTerm& s, const ScaffoldTerm& t, double tolerance) {
  if (s.kind != t.kind) return false;
  switch (s.kind) {
    case TermKind::point_point: return s.at == t.at && (s.p - t.p).norm() <= tolerance;
    case TermKind::point_line:
      return s.at == t.at && (((s.ka - t.ka).norm() <= tolerance && (s.kb - t.kb).norm() <= tolerance) ||
                              ((s.ka - t.kb).norm() <= tolerance && (s.kb - t.ka).norm() <= tolerance));
    case TermKind::perpendicular:
    case TermKind::parallel:  // d and -d give the same energy
      return (s.d - t.d).norm() <= tolerance || (s.d + t.d).norm() <= tolerance;
    case TermKind::equal_length: {
      const double ks = (s.ka - s.kb).norm(), kt = (t.ka - t.kb).norm();
      return std::abs(ks - kt) <= tolerance * std::max(ks, kt);
    }
  }
  return false;
}

std::vector<ScaffoldTerm> scaffold_candidates(const Vec3& a, const Vec3& b, const Network& network,
                                              const Workspace& workspace,
                                              const ScaffoldParams& params, double scale) {
  std::vector<ScaffoldTerm> terms;
  const double radius = scaled_threshold(params.point_distance, scale);
  const double radius2 = radius * radius;

  // Point terms (eq. 1, 2), per point of l.
  std::vector<LinePoint> points{LinePoint::start, LinePoint::end};
  if (params.midpoint_snapping) points.push_back(LinePoint::middle);
  // One keypoint is a candidate for one point of l only, the nearest (ties:
  // start, end, middle). Two points of l held at one keypoint make l a point:
  // an 8 cm line whose start and midpoint were both within 5 cm of the same
  // corner became 3 nm long (issue #18).
  auto claimed_elsewhere = [&](LinePoint at, const Vec3& keypoint) {
    const double own = (line_point(at, a, b) - keypoint).squaredNorm();
    return std::any_of(points.begin(), points.end(), [&](LinePoint other) {
      const double d = (line_point(other, a, b) - keypoint).squaredNorm();
      return other != at && (d < own || (d == own && other < at));
    });
  };
  for (LinePoint at : points) {
    const Vec3 x = line_point(at, a, b);
    std::vector<Vec3> seen;
    for (const KeypointHit& hit : network.keypoints_near(x, radius)) {
      const NetworkCurve* c = network.find_curve(hit.curve);
      if (!c || !is_scaffold_line(*c)) continue;
      const bool duplicate = std::any_of(seen.begin(), seen.end(), [&](const Vec3& s) {
        return (s - hit.position).norm() <= 1e-12;
      });
      if (duplicate || claimed_elsewhere(at, hit.position)) continue;
      seen.push_back(hit.position);
      ScaffoldTerm t;
      t.kind = TermKind::point_point;
      t.at = at;
      t.p = hit.position;
      t.curve = hit.curve;
      t.curve_t = c->keypoints[static_cast<std::size_t>(hit.keypoint)].t;
      if (term_energy(t, a, b) < radius2) terms.push_back(t);
    }
    if (at == LinePoint::middle) continue;  // point–line is for endpoints (§4.1)
    auto add_point_line = [&](CurveId id, const NetworkCurve& c) {
      ScaffoldTerm t;
      t.kind = TermKind::point_line;
      t.at = at;
      t.ka = c.curve.control_points.front();
      t.kb = c.curve.control_points.back();
      t.curve = id;
      const Vec3 e = t.kb - t.ka;
      if (e.norm() < min_length) return;
      t.curve_t = std::clamp(e.dot(x - t.ka) / e.squaredNorm(), 0.0, 1.0);
      if (term_energy(t, a, b) < radius2) terms.push_back(t);
    };
    if (params.point_line_reach == PointLineReach::line) {
      // Eq. 2 is the distance to k's infinite line, and its value on the
      // input decides inclusion: an end near the extension of a line counts.
      for (const auto& [id, c] : network.curves())
        if (is_scaffold_line(c)) add_point_line(id, c);
    } else {
      std::vector<CurveHit> hits = network.curves_near(x, radius);
      std::sort(hits.begin(), hits.end(),
                [](const CurveHit& l, const CurveHit& r) { return l.curve < r.curve; });
      for (const CurveHit& hit : hits)
        if (const NetworkCurve* c = network.find_curve(hit.curve); c && is_scaffold_line(*c))
          add_point_line(hit.curve, *c);
    }
  }

  // Direction and length terms (eq. 3–5) against every scaffold line.
  const double length = (b - a).norm();
  if (length < min_length) return terms;
  const double perpendicular_limit = std::pow(std::sin(params.angle_threshold), 2);
  const double parallel_limit = perpendicular_limit;  // sin²(angle) for both
  const double length_limit = params.equal_length_tolerance * params.equal_length_tolerance;
  for (const auto& [id, c] : network.curves()) {
    if (!is_scaffold_line(c)) continue;
    const Vec3 ka = c.curve.control_points.front(), kb = c.curve.control_points.back();
    const double k = (kb - ka).norm();
    if (k < min_length) continue;
    ScaffoldTerm t;
    t.curve = id;
    t.ka = ka;
    t.kb = kb;
    t.d = (kb - ka) / k;
    t.kind = TermKind::perpendicular;
    if (term_energy(t, a, b) < perpendicular_limit) terms.push_back(t);
    t.kind = TermKind::parallel;
    if (term_energy(t, a, b) < parallel_limit) terms.push_back(t);
    t.kind = TermKind::equal_length;
    if (term_energy(t, a, b) < length_limit) terms.push_back(t);
  }
  // The vertical axis is the one direction that is not a scaffold line
  // ("all existing keypoints, directions, and lines", §4.1): eq. 4 with
  // d = up (verticals) and eq. 3 with d = up (horizontals). Without the
  // latter a freehand base is never level, so a later vertical edge faces a
  // real conflict between up and the base's normal that IRLS may settle
  // differently per edge (README).
  if (workspace.up.norm() > min_length) {
    ScaffoldTerm t;
    t.d = workspace.up.normalized();
    t.curve = 0;
    t.kind = TermKind::parallel;
    if (params.vertical_parallel && term_energy(t, a, b) < parallel_limit) terms.push_back(t);
    t.kind = TermKind::perpendicular;
    if (params.vertical_perpendicular && term_energy(t, a, b) < perpendicular_limit)
      terms.push_back(t);
  }
  return terms;
}

}  // namespace sketchlab::scaffoldsketch
