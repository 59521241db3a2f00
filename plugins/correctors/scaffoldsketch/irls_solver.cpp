#include "irls_solver.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "sketchlab/plugin/budget.hpp"

namespace sketchlab::scaffoldsketch {
namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

constexpr double anchor_floor = 1e-6;  // 1/m²: the anchor when no term has any weight

double weighted_cost(const std::vector<ScaffoldTerm>& terms, const std::vector<double>& w,
                     const Vec3& a, const Vec3& b, const Vec3& a0, const Vec3& b0, double anchor) {
  double cost = anchor * ((a - a0).squaredNorm() + (b - b0).squaredNorm());
  for (std::size_t i = 0; i < terms.size(); ++i)
    if (w[i] > 0) cost += w[i] * term_energy(terms[i], a, b);
  return cost;
}

std::vector<double> energies_at(const std::vector<ScaffoldTerm>& terms, const Vec3& a,
                                const Vec3& b) {
  std::vector<double> e(terms.size());
  for (std::size_t i = 0; i < terms.size(); ++i) e[i] = term_energy(terms[i], a, b);
  return e;
}

// Gauss–Newton normal equations of Σ w_i |r_i|² from the factored
// Jacobians J_i = [fa·m, fb·m]: JᵀJ has blocks f f'·mᵀm, Jᵀr = (fa, fb)·mᵀr.
void normal_equations(const std::vector<ScaffoldTerm>& terms, const std::vector<double>& weights,
                      const Vec3& a, const Vec3& b, Mat6& h, Vec6& g) {
  h.setZero();
  g.setZero();
  Vec3 r;
  Mat3 m;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    if (weights[i] <= 0) continue;
    double fa = 0, fb = 0;
    const int rows = term_linearisation(terms[i], a, b, r, m, fa, fb);
    Mat3 mtm;
    Vec3 mtr;
    if (rows == 1) {
      const Vec3 row = m.row(0).transpose();
      mtm = weights[i] * (row * row.transpose());
      mtr = (weights[i] * r.x()) * row;
    } else {
      mtm = weights[i] * (m.transpose() * m);
      mtr = weights[i] * (m.transpose() * r);
    }
    h.topLeftCorner<3, 3>() += (fa * fa) * mtm;
    h.topRightCorner<3, 3>() += (fa * fb) * mtm;
    h.bottomRightCorner<3, 3>() += (fb * fb) * mtm;
    g.head<3>() += fa * mtr;
    g.tail<3>() += fb * mtr;
  }
  h.bottomLeftCorner<3, 3>() = h.topRightCorner<3, 3>().transpose();
}

}  // namespace

int minimise_weighted(const std::vector<ScaffoldTerm>& terms, const std::vector<double>& weights,
                      Vec3& a, Vec3& b, const Vec3& a0, const Vec3& b0, double anchor_ratio,
                      int max_steps) {
  Mat6 h;
  Vec6 g;
  normal_equations(terms, weights, a, b, h, g);
  // The anchor is a fixed fraction of the stiffest term's curvature, so it
  // scales with the IRLS weights (up to 1/ε): negligible for every kept term
  // (it moves a satisfied one by ~anchor_ratio times the distance to the
  // input), yet no longer below the damping and the rounding of the
  // gradient, which a direction no term constrains used to follow (issue
  // #18: after 61 strokes a line had moved 73 m).
  const double anchor = std::max(anchor_floor, anchor_ratio * h.diagonal().maxCoeff());
  double lambda = 1e-6;
  double cost = weighted_cost(terms, weights, a, b, a0, b0, anchor);
  int steps = 0;
  while (steps < max_steps && cost > 0) {
    h.diagonal().array() += anchor;
    g.head<3>() += anchor * (a - a0);
    g.tail<3>() += anchor * (b - b0);
    // Isotropic (Levenberg) damping: a multiple of the identity shares the
    // eigenvectors of JᵀWJ, so a damped step never mixes a constrained
    // direction into a free one. Marquardt's diag(JᵀWJ) does unless the line
    // is axis-aligned, and where the cost is flat nothing undoes the mix:
    // that collapsed a 12.7 cm line with a snapped start and a parallel term
    // to microns (issue #18). The solve is also independent of the world
    // axes now (§3.2: "no assumptions regarding world-space axes"). All six
    // unknowns are metres, so one scale serves.
    const double scale = h.diagonal().maxCoeff();
    bool accepted = false;
    Vec6 delta = Vec6::Zero();
    for (int attempt = 0; attempt < 30 && !accepted; ++attempt) {
      Mat6 damped = h;
      damped.diagonal().array() += lambda * scale;
      delta = damped.ldlt().solve(-g);
      if (!delta.allFinite()) {
        lambda *= 10;
        continue;
      }
      // Converged when the Gauss–Newton model promises no measurable
      // decrease: trying ever more damped steps at the rounding floor of
      // the cost only spends evaluations (it was most of the solve time).
      const double predicted = -g.dot(delta) - 0.5 * delta.dot(h * delta);
      if (!(predicted > 1e-15 * cost)) return steps;
      const Vec3 na = a + delta.head<3>(), nb = b + delta.tail<3>();
      const double next = weighted_cost(terms, weights, na, nb, a0, b0, anchor);
      if (next < cost) {
        a = na;
        b = nb;
        const double drop = cost - next;
        cost = next;
        lambda = std::max(lambda / 3, 1e-12);
        accepted = true;
        if (drop <= 1e-15 * cost) return steps + 1;
      } else {
        lambda *= 4;
      }
    }
    ++steps;
    const double size = 1.0 + std::max(a.norm(), b.norm());
    if (!accepted || delta.norm() <= 1e-15 * size) break;
    normal_equations(terms, weights, a, b, h, g);
  }
  return steps;
}

namespace {

// Terms with the same energy for every l (same_energy up to 1e-9) share
// their weight at every IRLS round (eq. 7 depends on C only), so
// Σ w_i C_i = Σ_g m_g w_g C_g over the distinct terms g with multiplicity
// m_g. Dense scaffolds have many such terms (parallel, perpendicular and
// equal-length terms against lines corrected parallel or equal); merging
// them is exact and keeps the solve small. Terms are binned by their
// quantised defining values; a near-equal pair split across two bins stays
// two terms, which is only slower.
struct MergedTerms {
  std::vector<ScaffoldTerm> unique;
  std::vector<double> multiplicity;
  std::vector<std::size_t> group;  // per input term: index into unique
};

MergedTerms merge_terms(const std::vector<ScaffoldTerm>& terms) {
  constexpr double quantum = 1e-10;
  constexpr double tolerance = 1e-9;
  using Key = std::array<long long, 7>;
  auto q = [](double v) { return std::llround(v / quantum); };
  MergedTerms m;
  m.group.resize(terms.size());
  std::map<Key, std::size_t> bins;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    const ScaffoldTerm& t = terms[i];
    Vec3 x = Vec3::Zero(), y = Vec3::Zero();
    switch (t.kind) {
      case TermKind::point_point: x = t.p; break;
      case TermKind::point_line:
        x = t.ka;
        y = t.kb;
        if (std::lexicographical_compare(y.data(), y.data() + 3, x.data(), x.data() + 3))
          std::swap(x, y);
        break;
      case TermKind::perpendicular:
      case TermKind::parallel: {
        x = t.d;
        int axis = 0;
        x.cwiseAbs().maxCoeff(&axis);
        if (x(axis) < 0) x = -x;  // d and -d give the same energy
        break;
      }
      case TermKind::equal_length: x.x() = (t.ka - t.kb).norm(); break;
    }
    std::size_t g = m.unique.size();
    if (x.allFinite() && y.allFinite() && x.cwiseAbs().maxCoeff() < 1e6 &&
        y.cwiseAbs().maxCoeff() < 1e6) {
      const Key key{static_cast<long long>(t.kind) * 3 + static_cast<long long>(t.at),
                    q(x.x()), q(x.y()), q(x.z()), q(y.x()), q(y.y()), q(y.z())};
      const auto [it, fresh] = bins.try_emplace(key, g);
      if (!fresh && same_energy(m.unique[it->second], t, tolerance)) g = it->second;
    }
    if (g == m.unique.size()) {
      m.unique.push_back(t);
      m.multiplicity.push_back(0.0);
    }
    m.multiplicity[g] += 1.0;
    m.group[i] = g;
  }
  return m;
}

// The second, lexicographic stage of eq. 6 with its anchor: among the lines
// satisfying the kept terms (weights > 0), the one closest to the input.
// Gauss–Newton on the kept residuals whose step, in the null space of their
// Jacobian, is the anchor's own step: δ = −(JᵀWJ)⁺JᵀWr + N Nᵀ(x0 − x). The
// penalty form alone crawls along a curved free set (a length held by
// equal-length terms while the line turns about a snapped end: millimetres
// left after 200 steps); here the next step's Gauss–Newton part removes the
// curvature error of the last, so a few steps suffice. Kept only if every
// kept term is still satisfied (C <= ε).
int keep_free_directions_drawn(const std::vector<ScaffoldTerm>& terms,
                               const std::vector<double>& weights, double eps, Vec3& a, Vec3& b,
                               const Vec3& a0, const Vec3& b0) {
  Vec3 x_a = a, x_b = b;
  Mat6 h;
  Vec6 g;
  int steps = 0;
  for (; steps < 20; ++steps) {
    normal_equations(terms, weights, x_a, x_b, h, g);
    const Eigen::SelfAdjointEigenSolver<Mat6> es(h);
    const double top = std::max(es.eigenvalues().maxCoeff(), 0.0);
    Vec6 pull;
    pull << a0 - x_a, b0 - x_b;
    Vec6 delta = Vec6::Zero();
    for (int k = 0; k < 6; ++k) {
      const auto v = es.eigenvectors().col(k);
      const double sigma = es.eigenvalues()(k);
      if (sigma > 1e-12 * top && top > 0) delta -= v * (v.dot(g) / sigma);  // singular values 1e-6
      else delta += v * v.dot(pull);
    }
    if (!delta.allFinite()) return steps;
    x_a += delta.head<3>();
    x_b += delta.tail<3>();
    if (delta.norm() <= 1e-13 * (1.0 + std::max(x_a.norm(), x_b.norm()))) break;
  }
  bool kept = x_a.allFinite() && x_b.allFinite();
  for (std::size_t i = 0; kept && i < terms.size(); ++i)
    kept = weights[i] <= 0 || term_energy(terms[i], x_a, x_b) <= eps;
  if (kept) {
    a = x_a;
    b = x_b;
  }
  return steps;
}

// When every kept term is a direction (eq. 3–4, invariant under scaling
// about the midpoint), the length is free: keep the drawn one. This is what
// the gradient of eq. 6 does from the input (it is orthogonal to l_b − l_a,
// so a descent keeps the length) and what the authors' code does; the
// anchor alone would give the projection, L·cos θ.
void keep_drawn_length(const std::vector<ScaffoldTerm>& terms, const std::vector<bool>& kept,
                       const Vec3& a0, const Vec3& b0, Vec3& a, Vec3& b) {
  bool any = false;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    if (!kept[i]) continue;
    if (terms[i].kind != TermKind::parallel && terms[i].kind != TermKind::perpendicular) return;
    any = true;
  }
  const double length = (b - a).norm();
  if (!any || !(length > 0)) return;
  const Vec3 m = 0.5 * (a + b), half = 0.5 * (b0 - a0).norm() / length * (b - a);
  a = m - half;
  b = m + half;
}

}  // namespace

IrlsResult solve_irls(const std::vector<ScaffoldTerm>& input_terms, const Vec3& a0,
                      const Vec3& b0, const IrlsOptions& options) {
  IrlsResult result;
  result.a = a0;
  result.b = b0;
  if (input_terms.empty()) {
    result.converged = true;
    return result;
  }
  const MergedTerms merged = merge_terms(input_terms);
  const std::vector<ScaffoldTerm>& terms = merged.unique;
  const std::size_t n = terms.size();
  const double eps = options.epsilon;
  std::vector<double> energy = energies_at(terms, a0, b0);
  std::vector<double> w(n), objective_weight(n);
  std::vector<bool> satisfied(n), now(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double w0 = terms[i].kind == TermKind::point_point ? options.point_point_weight
                                                             : options.other_weight;
    w[i] = w0 / (eps + energy[i]);  // iteration 0 of eq. 7 on the input line
    satisfied[i] = energy[i] <= eps;
  }

  Vec3 a = a0, b = b0;
  for (int k = 1; k <= options.max_iterations; ++k) {
    check_budget();  // issue 17: the per-event time budget
    const Vec3 pa = a, pb = b;
    for (std::size_t i = 0; i < n; ++i) objective_weight[i] = merged.multiplicity[i] * w[i];
    result.solver_steps += minimise_weighted(terms, objective_weight, a, b, a0, b0);  // eq. 6
    result.iterations = k;
    for (std::size_t i = 0; i < n; ++i) {
      energy[i] = term_energy(terms[i], a, b);
      w[i] = 1.0 / (eps + energy[i]);  // eq. 7
      now[i] = energy[i] <= eps;
    }
    const double moved = std::max((a - pa).norm(), (b - pb).norm());
    const bool stable = now == satisfied;
    std::swap(satisfied, now);
    if (stable && moved <= options.move_tolerance) {
      result.converged = true;
      break;
    }
  }

  // The binary limit of the weights: discarded terms drop out.
  for (std::size_t i = 0; i < n; ++i)
    objective_weight[i] = satisfied[i] ? merged.multiplicity[i] * w[i] : 0.0;
  Vec3 pa = a, pb = b;
  result.solver_steps += minimise_weighted(terms, objective_weight, pa, pb, a0, b0);
  if (pa.allFinite() && pb.allFinite()) {
    a = pa;
    b = pb;
  }
  result.solver_steps += keep_free_directions_drawn(terms, objective_weight, eps, a, b, a0, b0);
  if (options.direction_only_keeps_length) keep_drawn_length(terms, satisfied, a0, b0, a, b);
  const double input_length = (b0 - a0).norm();
  if (!a.allFinite() || !b.allFinite() || (b - a).norm() < 1e-9 * std::max(input_length, 1.0)) {
    a = a0;  // collapsed or diverged: keep what the user drew
    b = b0;
    result.converged = false;
    std::fill(satisfied.begin(), satisfied.end(), false);
  }
  result.a = a;
  result.b = b;
  const std::size_t count = input_terms.size();
  result.weights.resize(count);
  result.energies = energies_at(input_terms, a, b);
  result.enforced.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t g = merged.group[i];
    result.weights[i] = w[g];
    result.enforced[i] = satisfied[g] && result.energies[i] <= eps;
  }
  return result;
}

}  // namespace sketchlab::scaffoldsketch
