#include "mvc_curve.hpp"

#include <nlopt.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab::scaffoldsketch {

double menger_curvature(const Vec3& a, const Vec3& b, const Vec3& c, Mat3* grad) {
  const Vec3 ab = b - a, bc = c - b, ac = c - a;
  const double l1 = ab.norm(), l2 = bc.norm(), l3 = ac.norm();
  if (grad) grad->setZero();
  if (l1 < 1e-15 || l2 < 1e-15 || l3 < 1e-15) return 0.0;
  const Vec3 n = ab.cross(ac);
  const double area2 = n.norm();  // twice the triangle area
  const double k = 2.0 * area2 / (l1 * l2 * l3);
  if (grad && area2 > 1e-300) {
    const Vec3 nh = n / area2;
    // d log k = d|n|/|n| - Σ d l / l.
    const Vec3 dn_a = (b - c).cross(nh), dn_b = ac.cross(nh), dn_c = nh.cross(ab);
    grad->col(0) = k * (dn_a / area2 + ab / (l1 * l1) + ac / (l3 * l3));
    grad->col(1) = k * (dn_b / area2 - ab / (l1 * l1) + bc / (l2 * l2));
    grad->col(2) = k * (dn_c / area2 - bc / (l2 * l2) - ac / (l3 * l3));
  }
  return k;
}

double tangent_curvature(const Vec3& q, const Vec3& d, const Vec3& b, Vec3* grad) {
  const Vec3 v = b - q;
  const double v2 = v.squaredNorm();
  const Vec3 n = d.cross(v);
  const double area2 = n.norm();
  if (grad) grad->setZero();
  if (v2 < 1e-30) return 0.0;
  const double k = 2.0 * area2 / v2;
  // d|n|/dv = n̂ × d; d(1/|v|²)/dv = -2v/|v|⁴.
  if (grad && area2 > 1e-300) *grad = 2.0 * (n / area2).cross(d) / v2 - 2.0 * k * v / v2;
  return k;
}

namespace {

// One arclength sample: a point of segment k at fixed parameter u, affine in
// that segment's two magnitudes: b = base + x1·w1 - x2·w2.
struct SamplePoint {
  int segment = 0;
  Vec3 base = Vec3::Zero();
  Vec3 w1 = Vec3::Zero(), w2 = Vec3::Zero();
};

// A point of the curvature sequence of eq. 9: the Menger curvature (eq. 8)
// centred on a sample, or, at a keypoint, the curvature of the circle tangent
// to the keypoint's constrained direction through the neighbouring sample
// (the limit of eq. 8 with the third point moving into the keypoint along its
// tangent).
struct CurvatureSite {
  bool tangent = false;
  std::size_t sample = 0;  // Menger: the centre sample; tangent: the neighbour
  Vec3 q = Vec3::Zero(), d = Vec3::Zero();  // tangent: the keypoint and its direction
};

struct Problem {
  std::vector<SamplePoint> samples;
  std::vector<CurvatureSite> sites;  // in curve order
  bool closed = false;  // samples and sites wrap around (the seam point is not repeated)
  int evaluations = 0;
};

Curve build_curve(const std::vector<Vec3>& q, const std::vector<Vec3>& d,
                  const std::vector<double>& x, bool closed) {
  Curve c;
  c.kind = CurveKind::bezier;
  const std::size_t segs = q.size() - 1;
  c.control_points.reserve(3 * segs + 1);
  c.control_points.push_back(q[0]);
  for (std::size_t k = 0; k < segs; ++k) {
    c.control_points.push_back(q[k] + x[2 * k] * d[k]);
    c.control_points.push_back(q[k + 1] - x[2 * k + 1] * d[k + 1]);
    c.control_points.push_back(q[k + 1]);
  }
  c.sharp.assign(segs + 1, false);
  c.closed = closed;
  if (closed) c.control_points.back() = c.control_points.front();
  return c;
}

// Parameters u in [0,1) of a segment, uniform in arclength on its current
// shape (a 64-chord table), `count` of them starting at u = 0.
std::vector<double> arclength_spread(const std::array<Vec3, 4>& p, int count) {
  constexpr int table = 64;
  std::array<double, table + 1> s{};
  Vec3 prev = p[0];
  for (int i = 1; i <= table; ++i) {
    const Vec3 cur = bezier_point(p, static_cast<double>(i) / table);
    s[i] = s[i - 1] + (cur - prev).norm();
    prev = cur;
  }
  std::vector<double> u(static_cast<std::size_t>(count));
  for (int j = 0; j < count; ++j) {
    const double target = s[table] * j / count;
    const auto it = std::lower_bound(s.begin(), s.end(), target);
    const int i = std::clamp(static_cast<int>(it - s.begin()), 1, table);
    const double span = s[i] - s[i - 1];
    const double f = span > 0 ? (target - s[i - 1]) / span : 0.0;
    u[static_cast<std::size_t>(j)] = (i - 1 + f) / table;
  }
  return u;
}

Problem make_problem(const std::vector<Vec3>& q, const std::vector<Vec3>& d,
                     const std::vector<double>& x, bool closed, int per_segment,
                     bool tangent_sites) {
  const Curve c = build_curve(q, d, x, closed);
  const int segs = c.segment_count();
  std::vector<double> lengths(static_cast<std::size_t>(segs));
  double total = 0;
  for (int k = 0; k < segs; ++k) {
    const auto p = segment_points(c, k);
    double len = 0;
    Vec3 prev = p[0];
    for (int i = 1; i <= 32; ++i) {
      const Vec3 cur = bezier_point(p, i / 32.0);
      len += (cur - prev).norm();
      prev = cur;
    }
    lengths[static_cast<std::size_t>(k)] = len;
    total += len;
  }
  const double spacing = total / (static_cast<double>(per_segment) * segs);
  Problem problem;
  problem.closed = closed;
  std::vector<int> keypoint_at;  // per sample: the keypoint there, or -1
  for (int k = 0; k < segs; ++k) {
    const int count = std::max(
        2, static_cast<int>(std::lround(lengths[static_cast<std::size_t>(k)] / spacing)));
    const auto p = segment_points(c, k);
    for (double u : arclength_spread(p, count)) {
      const double b0 = (1 - u) * (1 - u) * (1 - u), b1 = 3 * u * (1 - u) * (1 - u),
                   b2 = 3 * u * u * (1 - u), b3 = u * u * u;
      SamplePoint s;
      s.segment = k;
      s.base = (b0 + b1) * q[static_cast<std::size_t>(k)] + (b2 + b3) * q[static_cast<std::size_t>(k) + 1];
      s.w1 = b1 * d[static_cast<std::size_t>(k)];
      s.w2 = b2 * d[static_cast<std::size_t>(k) + 1];
      keypoint_at.push_back(u == 0.0 ? k : -1);
      problem.samples.push_back(s);
    }
  }
  if (!closed) {  // the last keypoint closes the open curve
    SamplePoint s;
    s.segment = segs - 1;
    s.base = q.back();
    keypoint_at.push_back(segs);
    problem.samples.push_back(s);
  }

  // The curvature sequence: Menger at every sample with two neighbours;
  // with tangent_sites, at each keypoint also the tangent circle toward the
  // sample before and the one after (the curve ends have only one).
  const std::size_t n = problem.samples.size();
  auto tangent_site = [&](int k, std::size_t neighbour) {
    CurvatureSite site;
    site.tangent = true;
    site.sample = neighbour;
    site.q = q[static_cast<std::size_t>(k)];
    site.d = d[static_cast<std::size_t>(k)];
    problem.sites.push_back(site);
  };
  for (std::size_t i = 0; i < n; ++i) {
    const bool has_before = closed || i > 0, has_after = closed || i + 1 < n;
    const int k = keypoint_at[i];
    if (tangent_sites && k >= 0 && has_before) tangent_site(k, (i + n - 1) % n);
    if (has_before && has_after) problem.sites.push_back(CurvatureSite{false, i, {}, {}});
    if (tangent_sites && k >= 0 && has_after) tangent_site(k, (i + 1) % n);
  }
  return problem;
}

// Eq. 9 over the curvature sequence of the problem's sites.
double objective(const Problem& pb, const std::vector<double>& x, std::vector<double>* grad) {
  const std::size_t n = pb.samples.size();
  std::vector<Vec3> b(n);
  for (std::size_t i = 0; i < n; ++i) {
    const SamplePoint& s = pb.samples[i];
    const auto k = static_cast<std::size_t>(s.segment);
    b[i] = s.base + x[2 * k] * s.w1 - x[2 * k + 1] * s.w2;
  }
  const std::size_t m = pb.sites.size();
  std::vector<double> c(m);
  std::vector<Mat3> g(grad ? m : 0);  // Menger: one column per point; tangent: column 0
  auto before = [&](std::size_t i) { return (i + n - 1) % n; };
  auto after = [&](std::size_t i) { return (i + 1) % n; };
  for (std::size_t j = 0; j < m; ++j) {
    const CurvatureSite& site = pb.sites[j];
    if (site.tangent) {
      Vec3 gv;
      c[j] = tangent_curvature(site.q, site.d, b[site.sample], grad ? &gv : nullptr);
      if (grad) g[j].col(0) = gv;
    } else {
      const std::size_t i = site.sample;
      c[j] = menger_curvature(b[before(i)], b[i], b[after(i)], grad ? &g[j] : nullptr);
    }
  }
  const std::size_t pairs = pb.closed ? m : (m > 0 ? m - 1 : 0);
  double f = 0;
  std::vector<double> df(m, 0.0);
  for (std::size_t j = 0; j < pairs; ++j) {
    const std::size_t j2 = (j + 1) % m;
    const double diff = c[j] - c[j2];
    f += diff * diff;
    df[j] += 2 * diff;
    df[j2] -= 2 * diff;
  }
  if (grad) {
    std::fill(grad->begin(), grad->end(), 0.0);
    auto add = [&](std::size_t sample, const Vec3& dp) {
      const SamplePoint& s = pb.samples[sample];
      const auto k = static_cast<std::size_t>(s.segment);
      (*grad)[2 * k] += dp.dot(s.w1);
      (*grad)[2 * k + 1] -= dp.dot(s.w2);
    };
    for (std::size_t j = 0; j < m; ++j) {
      if (df[j] == 0.0) continue;
      const CurvatureSite& site = pb.sites[j];
      if (site.tangent) {
        add(site.sample, df[j] * g[j].col(0));
      } else {
        const std::size_t i = site.sample;
        const std::size_t idx[3] = {before(i), i, after(i)};
        for (int r = 0; r < 3; ++r) add(idx[r], df[j] * g[j].col(r));
      }
    }
  }
  return f;
}

double nlopt_objective(const std::vector<double>& x, std::vector<double>& grad, void* data) {
  auto* pb = static_cast<Problem*>(data);
  ++pb->evaluations;
  return objective(*pb, x, grad.empty() ? nullptr : &grad);
}

std::string result_name(nlopt::result r) {
  switch (r) {
    case nlopt::SUCCESS: return "success";
    case nlopt::STOPVAL_REACHED: return "stopval";
    case nlopt::FTOL_REACHED: return "ftol";
    case nlopt::XTOL_REACHED: return "xtol";
    case nlopt::MAXEVAL_REACHED: return "maxeval";
    case nlopt::MAXTIME_REACHED: return "maxtime";
    default: return "failure";
  }
}

}  // namespace

MvcResult fit_mvc_curve(const std::vector<Vec3>& q, const std::vector<Vec3>& d, bool closed,
                        const ShapeParams& params) {
  const std::size_t m = q.size();
  if (m < 2 || d.size() != m)
    throw std::invalid_argument("fit_mvc_curve: need at least 2 keypoints and one tangent each");
  for (std::size_t i = 0; i < m; ++i) {
    if (!q[i].allFinite() || !d[i].allFinite() || std::abs(d[i].norm() - 1.0) > 1e-6)
      throw std::invalid_argument("fit_mvc_curve: keypoint " + std::to_string(i) +
                                  " is not finite or its tangent is not unit");
    if (i + 1 < m && (q[i + 1] - q[i]).norm() < 1e-12)
      throw std::invalid_argument("fit_mvc_curve: keypoints " + std::to_string(i) + " and " +
                                  std::to_string(i + 1) + " coincide");
  }
  const std::size_t segs = m - 1;
  std::vector<double> x(2 * segs), lower(2 * segs), upper(2 * segs);
  for (std::size_t k = 0; k < segs; ++k) {
    const double chord = (q[k + 1] - q[k]).norm();
    x[2 * k] = x[2 * k + 1] = chord / 3;  // §4.2.2 initialisation: no cusps
    lower[2 * k] = lower[2 * k + 1] = 1e-3 * chord;
    upper[2 * k] = upper[2 * k + 1] = 3 * chord;
  }
  MvcResult out;
  const int per_segment = std::max(2, params.samples_per_segment);
  for (int round = 0; round < 2; ++round) {
    Problem pb = make_problem(q, d, x, closed, per_segment, params.tangent_curvature);
    if (round == 0) out.initial_objective = objective(pb, x, nullptr);
    nlopt::opt opt(nlopt::LD_LBFGS, static_cast<unsigned>(x.size()));
    opt.set_lower_bounds(lower);
    opt.set_upper_bounds(upper);
    opt.set_min_objective(nlopt_objective, &pb);
    opt.set_ftol_rel(1e-12);
    opt.set_xtol_rel(1e-10);
    opt.set_maxeval(std::max(10, params.max_evaluations));
    double f = 0;
    std::vector<double> trial = x;
    try {
      out.status = result_name(opt.optimize(trial, f));
      if (std::all_of(trial.begin(), trial.end(), [](double v) { return std::isfinite(v); }))
        x = trial;
    } catch (const nlopt::roundoff_limited&) {
      out.status = "roundoff";  // converged as far as doubles allow
      if (std::all_of(trial.begin(), trial.end(), [](double v) { return std::isfinite(v); }))
        x = trial;
    } catch (const std::exception& e) {
      out.status = std::string("failure: ") + e.what();
    }
    out.evaluations += pb.evaluations;
    out.rounds = round + 1;
    out.objective = objective(pb, x, nullptr);
  }
  out.magnitudes = x;
  out.curve = build_curve(q, d, x, closed);
  return out;
}

}  // namespace sketchlab::scaffoldsketch
