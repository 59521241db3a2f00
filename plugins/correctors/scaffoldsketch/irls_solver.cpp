#include "irls_solver.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace sketchlab::scaffoldsketch {
namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

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

}  // namespace

int minimise_weighted(const std::vector<ScaffoldTerm>& terms, const std::vector<double>& weights,
                      Vec3& a, Vec3& b, const Vec3& a0, const Vec3& b0, double anchor,
                      int max_steps) {
  double lambda = 1e-6;
  double cost = weighted_cost(terms, weights, a, b, a0, b0, anchor);
  int steps = 0;
  Vec3 r;
  Eigen::Matrix<double, 3, 6> j;
  while (steps < max_steps && cost > 0) {
    Mat6 h = anchor * Mat6::Identity();
    Vec6 g;
    g << anchor * (a - a0), anchor * (b - b0);
    for (std::size_t i = 0; i < terms.size(); ++i) {
      if (weights[i] <= 0) continue;
      const int rows = term_residual(terms[i], a, b, r, j);
      const auto jr = j.topRows(rows);
      h.noalias() += weights[i] * jr.transpose() * jr;
      g.noalias() += weights[i] * jr.transpose() * r.head(rows);
    }
    // Isotropic floor on the damping: directions no term constrains get
    // (numerically) zero steps instead of rounding noise over a tiny pivot.
    const double floor = 1e-14 * std::max(h.diagonal().maxCoeff(), 1e-300);
    bool accepted = false;
    Vec6 delta = Vec6::Zero();
    for (int attempt = 0; attempt < 30 && !accepted; ++attempt) {
      Mat6 damped = h;
      for (int k = 0; k < 6; ++k) damped(k, k) += lambda * h(k, k) + floor;
      delta = damped.ldlt().solve(-g);
      if (!delta.allFinite()) {
        lambda *= 10;
        continue;
      }
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
    const double scale = 1.0 + std::max(a.norm(), b.norm());
    if (!accepted || delta.norm() <= 1e-15 * scale) break;
  }
  return steps;
}

IrlsResult solve_irls(const std::vector<ScaffoldTerm>& terms, const Vec3& a0, const Vec3& b0,
                      const IrlsOptions& options) {
  IrlsResult result;
  result.a = a0;
  result.b = b0;
  const std::size_t n = terms.size();
  const double eps = options.epsilon;
  std::vector<double> energy = energies_at(terms, a0, b0);
  std::vector<double> w(n);
  std::vector<bool> satisfied(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double w0 = terms[i].kind == TermKind::point_point ? options.point_point_weight
                                                             : options.other_weight;
    w[i] = w0 / (eps + energy[i]);  // iteration 0 of eq. 7 on the input line
    satisfied[i] = energy[i] <= eps;
  }
  if (n == 0) {
    result.converged = true;
    return result;
  }

  Vec3 a = a0, b = b0;
  for (int k = 1; k <= options.max_iterations; ++k) {
    const Vec3 pa = a, pb = b;
    result.solver_steps += minimise_weighted(terms, w, a, b, a0, b0);  // eq. 6
    result.iterations = k;
    energy = energies_at(terms, a, b);
    std::vector<bool> now(n);
    for (std::size_t i = 0; i < n; ++i) {
      w[i] = 1.0 / (eps + energy[i]);  // eq. 7
      now[i] = energy[i] <= eps;
    }
    const double moved = std::max((a - pa).norm(), (b - pb).norm());
    const bool stable = now == satisfied;
    satisfied = std::move(now);
    if (stable && moved <= options.move_tolerance) {
      result.converged = true;
      break;
    }
  }

  // The binary limit of the weights: discarded terms drop out.
  std::vector<double> polish(n);
  for (std::size_t i = 0; i < n; ++i) polish[i] = satisfied[i] ? w[i] : 0.0;
  Vec3 pa = a, pb = b;
  result.solver_steps += minimise_weighted(terms, polish, pa, pb, a0, b0);
  if (pa.allFinite() && pb.allFinite()) {
    a = pa;
    b = pb;
  }
  const double input_length = (b0 - a0).norm();
  if (!a.allFinite() || !b.allFinite() || (b - a).norm() < 1e-9 * std::max(input_length, 1.0)) {
    a = a0;  // collapsed or diverged: keep what the user drew
    b = b0;
    result.converged = false;
    std::fill(satisfied.begin(), satisfied.end(), false);
  }
  result.a = a;
  result.b = b;
  result.weights = w;
  result.energies = energies_at(terms, a, b);
  result.enforced.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    result.enforced[i] = satisfied[i] && result.energies[i] <= eps;
  return result;
}

}  // namespace sketchlab::scaffoldsketch
