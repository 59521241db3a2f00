#include "hermite_interpolant.hpp"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>


namespace sketchlab::hermite_rbf {
namespace {

// One linear functional: evaluation at x (value) or d·∇ at x (directional).
struct Functional {
  Vec3 x;
  bool directional = false;
  Vec3 d = Vec3::Zero();
  double rhs = 0.0;
  int center = 0;
};

// Kernel entries for φ(r) = r³ between functionals k and l (§ Macêdo et al.:
// A_kl = λ_k^x λ_l^y φ(‖x − y‖)), with v = x_k − x_l:
//   value-value        r³
//   value_k, dir_l     −d_l·g(v),   g(v) = ∇φ(v) = 3 r v
//   dir_k, value_l      d_k·g(v)
//   dir_k, dir_l       −d_kᵀ H(v) d_l,   H(v) = 3 (r I + v vᵀ / r)   (0 at r = 0)
double kernel(const Functional& k, const Functional& l) {
  const Vec3 v = k.x - l.x;
  const double r = v.norm();
  if (!k.directional && !l.directional) return r * r * r;
  if (!k.directional) return -3.0 * r * l.d.dot(v);
  if (!l.directional) return 3.0 * r * k.d.dot(v);
  if (r == 0.0) return 0.0;
  return -3.0 * (r * k.d.dot(l.d) + k.d.dot(v) * l.d.dot(v) / r);
}

}  // namespace

template <bool gradient>
double HermiteInterpolant::evaluate(const Vec3& x, Vec3* g) const {
  const Vec3 y = (x - origin) / scale;
  const double px = y.x(), py = y.y(), pz = y.z();
  const double *cx = centers.x.data(), *cy = centers.y.data(), *cz = centers.z.data(), *al = centers.alpha.data(),
               *bx = centers.bx.data(), *by = centers.by.data(), *bz = centers.bz.data();
  const std::size_t n = centers.size();
  // One sequential sum per component (bound by sqrt and division throughput;
  // measured: split lanes that vectorise are slower here).
  double f = 0.0, gx = 0.0, gy = 0.0, gz = 0.0;
  for (std::size_t c = 0; c < n; ++c) {
    const double vx = px - cx[c], vy = py - cy[c], vz = pz - cz[c];
    const double r2 = vx * vx + vy * vy + vz * vz;
    const double r = std::sqrt(r2);
    const double bv = bx[c] * vx + by[c] * vy + bz[c] * vz;
    f += r * (al[c] * r2 - 3.0 * bv);
    if constexpr (gradient) {
      // ∇(α r³) = 3α r v;  ∇(−β·g(v)) = −H(v) β = −3 (r β + (β·v) v / r)
      const double inv = bv / (r + 1e-300);  // v = 0 and bv = 0 at r = 0: branch-free
      const double k = 3.0 * (al[c] * r - inv);
      gx += k * vx - 3.0 * r * bx[c];
      gy += k * vy - 3.0 * r * by[c];
      gz += k * vz - 3.0 * r * bz[c];
    }
  }
  if constexpr (gradient) *g = Vec3(gx, gy, gz) + a;
  return scale * (f + a0 + a.dot(y));
}

double HermiteInterpolant::value(const Vec3& x) const { return evaluate<false>(x, nullptr); }

double HermiteInterpolant::value_gradient(const Vec3& x, Vec3& gradient) const { return evaluate<true>(x, &gradient); }

HermiteInterpolant fit_hermite_rbf(const HermiteConstraints& cons, const SolveParams& params, SolveReport& report) {
  check_constraints(cons);
  Box3 box;
  for (const Vec3& p : cons.points) box.extend(p);
  for (const Vec3& p : cons.normal_points) box.extend(p);
  for (const Vec3& p : cons.tangent_points) box.extend(p);
  HermiteInterpolant f = solve_hermite_rbf(cons, box.center(), box.diagonal().norm(), params, report);
  measure_residuals(f, cons, report);
  return f;
}

HermiteInterpolant solve_hermite_rbf(const HermiteConstraints& cons, const Vec3& origin, double scale,
                                     const SolveParams& params, SolveReport& report) {
  const auto start = std::chrono::steady_clock::now();
  HermiteInterpolant f;
  f.origin = origin;
  f.scale = scale;

  // Functionals and the centres they share (exact position matches).
  std::vector<Functional> fn;
  std::map<std::array<double, 3>, int> center_of;
  auto position = [&](int c) {
    const auto k = static_cast<std::size_t>(c);
    return Vec3(f.centers.x[k], f.centers.y[k], f.centers.z[k]);
  };
  auto center = [&](const Vec3& p) {
    const Vec3 y = (p - f.origin) / f.scale;
    const auto [it, added] = center_of.try_emplace({y.x(), y.y(), y.z()}, static_cast<int>(f.centers.size()));
    if (added) f.centers.add(y);
    return it->second;
  };
  for (const Vec3& p : cons.points) {
    const int c = center(p);
    fn.push_back({position(c), false, Vec3::Zero(), 0.0, c});
  }
  for (std::size_t i = 0; i < cons.tangents.size(); ++i) {
    const int c = center(cons.tangent_points[i]);
    fn.push_back({position(c), true, cons.tangents[i].normalized(), 0.0, c});
  }
  for (std::size_t i = 0; i < cons.normals.size(); ++i) {
    const int c = center(cons.normal_points[i]);
    const Vec3 n = cons.normals[i].normalized();
    for (int axis = 0; axis < 3; ++axis)
      fn.push_back({position(c), true, Vec3::Unit(axis), n[axis], c});
  }
  const auto m = static_cast<Eigen::Index>(fn.size());
  report.unknowns = fn.size();

  Eigen::MatrixXd A(m, m);
  Eigen::MatrixXd P(m, 4);
  Eigen::VectorXd b(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    const Functional& fk = fn[static_cast<std::size_t>(k)];
    for (Eigen::Index l = 0; l <= k; ++l) A(k, l) = A(l, k) = kernel(fk, fn[static_cast<std::size_t>(l)]);
    if (fk.directional)
      P.row(k) << 0.0, fk.d.x(), fk.d.y(), fk.d.z();
    else
      P.row(k) << 1.0, fk.x.x(), fk.x.y(), fk.x.z();
    b(k) = fk.rhs;
  }

  // Null-space method: c = Q₂γ satisfies Pᵀc = 0; Q₂ᵀ(A + λI)Q₂ γ = Q₂ᵀb.
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(P);
  const auto rank = qr.rank();
  report.polynomial_rank = static_cast<int>(rank);
  const auto q = qr.householderQ();
  A.applyOnTheLeft(q.transpose());
  A.applyOnTheRight(q);
  Eigen::VectorXd qb = b;
  qb.applyOnTheLeft(q.transpose());
  const Eigen::Index nk = m - rank;
  if (nk < 1) throw std::invalid_argument("hermite_rbf: degenerate input: too few constraints");
  auto K = A.bottomRightCorner(nk, nk);
  const Eigen::VectorXd diagonal = K.diagonal();
  double lambda = params.regularizer;
  Eigen::VectorXd gamma;
  for (int attempt = 0;; ++attempt) {
    K.diagonal() = diagonal.array() + lambda;
    // In place: LLT overwrites the lower triangle only; the upper one keeps Kᵀ for a retry.
    Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(K);
    if (llt.info() == Eigen::Success) {
      gamma = llt.solve(qb.tail(nk));
      if (gamma.allFinite()) break;
    }
    if (attempt >= 8) throw std::runtime_error("hermite_rbf: the kernel system stays singular (λ up to " + std::to_string(lambda) + ")");
    K.triangularView<Eigen::StrictlyLower>() = K.transpose();
    lambda = lambda > 0.0 ? lambda * 100.0 : 1e-12;
  }
  report.regularizer = lambda;
  // Polynomial: R a = (Qᵀb)_head − (QᵀAQ)_{head,tail} γ (upper block is intact).
  Eigen::VectorXd poly = Eigen::VectorXd::Zero(4);
  if (rank > 0) {
    const Eigen::VectorXd head = qb.head(rank) - A.topRightCorner(rank, nk) * gamma;
    const Eigen::VectorXd z = qr.matrixR().topLeftCorner(rank, rank).triangularView<Eigen::Upper>().solve(head);
    Eigen::VectorXd full = Eigen::VectorXd::Zero(4);
    full.head(rank) = z;
    poly = qr.colsPermutation() * full;
  }
  Eigen::VectorXd c = Eigen::VectorXd::Zero(m);
  c.tail(nk) = gamma;
  c.applyOnTheLeft(q);
  for (Eigen::Index k = 0; k < m; ++k) {
    const Functional& fk = fn[static_cast<std::size_t>(k)];
    const auto i = static_cast<std::size_t>(fk.center);
    if (fk.directional) {
      f.centers.bx[i] += c(k) * fk.d.x();
      f.centers.by[i] += c(k) * fk.d.y();
      f.centers.bz[i] += c(k) * fk.d.z();
    } else {
      f.centers.alpha[i] += c(k);
    }
  }
  f.a0 = poly(0);
  f.a = poly.tail<3>();
  report.solve_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return f;
}

void measure_residuals(const ImplicitFunction& f, const HermiteConstraints& cons, SolveReport& report) {
  report.residual_point = report.residual_normal = report.residual_tangent = 0.0;
  Vec3 g;
  for (const Vec3& p : cons.points) report.residual_point = std::max(report.residual_point, std::abs(f.value(p)));
  for (std::size_t i = 0; i < cons.normals.size(); ++i) {
    f.value_gradient(cons.normal_points[i], g);
    report.residual_normal = std::max(report.residual_normal, (g - cons.normals[i].normalized()).norm());
  }
  for (std::size_t i = 0; i < cons.tangents.size(); ++i) {
    f.value_gradient(cons.tangent_points[i], g);
    report.residual_tangent = std::max(report.residual_tangent, std::abs(g.dot(cons.tangents[i].normalized())));
  }
}

}  // namespace sketchlab::hermite_rbf
