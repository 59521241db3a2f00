#include "kkt_solve.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Eigen/Dense>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <optional>

namespace sketchlab::cassie {
namespace {

double span_of(const std::vector<Vec3>& p, double min_edge) {
  // L = max_i ||P̄_0^i − P̄_0^0|| over the Bézier start points (eq. 3.2).
  double l = 0.0;
  for (std::size_t i = 0; i < p.size(); i += 3) l = std::max(l, (p[i] - p[0]).norm());
  if (p.size() > 1) l = std::max(l, (p.back() - p[0]).norm());
  return std::max(l, min_edge);
}

double edge_length(const std::vector<Vec3>& p, std::size_t i, double min_edge) {
  return std::max((p[i + 1] - p[i]).norm(), min_edge);
}

void add_block(std::vector<Eigen::Triplet<double>>& t, int i, int j, const Mat3& m) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (m(r, c) != 0.0) t.emplace_back(3 * i + r, 3 * j + c, m(r, c));
}

// Quadratic form eᵀQe on the edge e = P_{i+1} − P_i.
void add_edge_form(std::vector<Eigen::Triplet<double>>& t, int i, const Mat3& q) {
  add_block(t, i, i, q);
  add_block(t, i + 1, i + 1, q);
  add_block(t, i, i + 1, -q);
  add_block(t, i + 1, i, -q);
}

double position_scale(const std::vector<Vec3>& p, double min_edge, const FidelityScale& f) {
  return f.position_scale > 0 ? f.position_scale : span_of(p, min_edge);
}

// Eq. 3.11 by block elimination (range-space method): A is SPD (the
// position term of eq. 3.2 is positive definite) and banded, so
// P = A⁻¹(B − CᵀΛ) with (C A⁻¹ Cᵀ) Λ = C A⁻¹ B − d, the Schur complement
// dense; then one step of iterative refinement on the full KKT residual.
// The control points, or none when a factorisation fails or the result is
// not finite.
std::optional<Eigen::VectorXd> solve_range_space(const std::vector<Eigen::Triplet<double>>& a,
                                                 const std::vector<Eigen::Triplet<double>>& c,
                                                 const Eigen::VectorXd& rhs, const Eigen::VectorXd& dv) {
  const Eigen::Index n = rhs.size(), nc = dv.size();
  Eigen::SparseMatrix<double> am(n, n), cm(nc, n);
  am.setFromTriplets(a.begin(), a.end());
  cm.setFromTriplets(c.begin(), c.end());
  // A is block tridiagonal (3×3 blocks, control points in curve order): the
  // natural ordering has no fill, so no reordering is computed.
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> ldlt(am);
  if (ldlt.info() != Eigen::Success) return std::nullopt;
  Eigen::MatrixXd y;  // A⁻¹Cᵀ, n x nc
  Eigen::LDLT<Eigen::MatrixXd> schur;
  if (nc > 0) {
    y = ldlt.solve(Eigen::MatrixXd(cm.transpose()));
    const Eigen::MatrixXd sm = cm * y;
    schur.compute(sm);
    if (schur.info() != Eigen::Success) return std::nullopt;
  }
  auto solve = [&](const Eigen::VectorXd& r1, const Eigen::VectorXd& r2, Eigen::VectorXd& px,
                   Eigen::VectorXd& lx) {
    const Eigen::VectorXd z = ldlt.solve(r1);
    if (nc == 0) {
      px = z;
      lx.resize(0);
      return;
    }
    lx = schur.solve(cm * z - r2);
    px = z - y * lx;
  };
  Eigen::VectorXd x, lambda;
  solve(rhs, dv, x, lambda);
  if (!x.allFinite() || !lambda.allFinite()) return std::nullopt;
  const Eigen::VectorXd r1 =
      rhs - am * x - (nc ? Eigen::VectorXd(cm.transpose() * lambda) : Eigen::VectorXd::Zero(n));
  const Eigen::VectorXd r2 = dv - cm * x;
  Eigen::VectorXd dx, dl;
  solve(r1, r2, dx, dl);
  if (dx.allFinite()) x += dx;
  if (!x.allFinite()) return std::nullopt;
  return x;
}

// Eq. 3.11 as one sparse matrix [A Cᵀ; C 0], LU-factorised with a
// fill-reducing ordering (COLAMD), then one step of iterative refinement.
// Every row of it couples neighbouring control points, so the work grows
// about linearly with the segments where the dense Schur complement above
// grows with the cube of the constraint rows. Returns as above.
std::optional<Eigen::VectorXd> solve_sparse_lu(const std::vector<Eigen::Triplet<double>>& a,
                                               const std::vector<Eigen::Triplet<double>>& c,
                                               const Eigen::VectorXd& rhs, const Eigen::VectorXd& dv) {
  const Eigen::Index n = rhs.size(), nc = dv.size();
  std::vector<Eigen::Triplet<double>> t = a;
  t.reserve(a.size() + 2 * c.size());
  for (const Eigen::Triplet<double>& e : c) {
    t.emplace_back(n + e.row(), e.col(), e.value());
    t.emplace_back(e.col(), n + e.row(), e.value());
  }
  Eigen::SparseMatrix<double> km(n + nc, n + nc);
  km.setFromTriplets(t.begin(), t.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  lu.compute(km);
  if (lu.info() != Eigen::Success) return std::nullopt;
  Eigen::VectorXd b(n + nc);
  b << rhs, dv;
  Eigen::VectorXd sol = lu.solve(b);
  if (!sol.allFinite()) return std::nullopt;
  const Eigen::VectorXd step = lu.solve(Eigen::VectorXd(b - km * sol));
  if (step.allFinite()) sol += step;
  return Eigen::VectorXd(sol.head(n));
}

}  // namespace

double fidelity_energy(const std::vector<Vec3>& input, const std::vector<Vec3>& points,
                       double min_edge, const FidelityScale& scale) {
  const std::size_t m = input.size();
  if (m < 2 || points.size() != m) return 0.0;
  const double l = position_scale(input, min_edge, scale);
  double pos = 0.0, slope = 0.0;
  for (std::size_t i = 0; i < m; ++i) pos += (points[i] - input[i]).squaredNorm();
  for (std::size_t i = 0; i + 1 < m; ++i) {
    const double e = edge_length(input, i, min_edge);
    slope += ((points[i + 1] - points[i]) - (input[i + 1] - input[i])).squaredNorm() / (e * e);
  }
  return scale.factor * (pos / (static_cast<double>(m) * l * l) + slope / static_cast<double>(m - 1));
}

SolveResult solve_constrained(const SolveProblem& pr) {
  SolveResult res;
  const std::vector<Vec3>& p0 = pr.input.control_points;
  const int m = static_cast<int>(p0.size());
  if (m < 2) return res;
  const int n = 3 * m;
  const double me = pr.min_edge;
  std::vector<Eigen::Triplet<double>> a;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);

  // E_fidelity (eq. 3.2): position term and slope term. A·P − B is half the
  // gradient, consistently for every term.
  const double f = pr.fidelity.factor;
  const double w_pos = f / (m * std::pow(position_scale(p0, me, pr.fidelity), 2));
  for (int i = 0; i < m; ++i) {
    add_block(a, i, i, w_pos * Mat3::Identity());
    rhs.segment<3>(3 * i) += w_pos * p0[i];
  }
  for (int i = 0; i + 1 < m; ++i) {
    const double e = edge_length(p0, i, me);
    const double w = f / ((m - 1) * e * e);
    add_edge_form(a, i, w * Mat3::Identity());
    const Vec3 eb = p0[i + 1] - p0[i];
    rhs.segment<3>(3 * (i + 1)) += w * eb;
    rhs.segment<3>(3 * i) -= w * eb;
  }
  // E_tangent (eq. 3.8): ||e × T||² = eᵀ(I − TTᵀ)e, divided by |ē|² so that it
  // measures sin² of the misalignment (dimensionless like E_fidelity).
  for (const TangentTarget& tt : pr.tangents) {
    const int i = tt.index < m - 1 ? tt.index : m - 2;
    const double e = edge_length(p0, i, me);
    const Vec3 d = tt.direction.normalized();
    add_edge_form(a, i, (tt.weight / (e * e)) * (Mat3::Identity() - d * d.transpose()));
  }
  // E_planar (eq. 3.9): Σ (e·n)², each edge normalised like the slope term.
  if (pr.plane_normal) {
    const Vec3 nn = pr.plane_normal->normalized();
    const Mat3 q = nn * nn.transpose();
    for (int i = 0; i + 1 < m; ++i) {
      const double e = edge_length(p0, i, me);
      add_edge_form(a, i, (pr.planarity_weight / ((m - 1) * e * e)) * q);
    }
  }

  // Hard constraints C·P = d.
  std::vector<Eigen::Triplet<double>> c;
  std::vector<double> d;
  auto row = [&](int var, double v, int r) { c.emplace_back(r, var, v); };
  const int k_count = pr.input.segment_count();
  for (int k = 1; k < k_count; ++k) {
    const int j = 3 * k;
    if (static_cast<std::size_t>(k) < pr.input.sharp.size() && pr.input.sharp[k]) continue;
    const double la = (p0[j] - p0[j - 1]).norm(), lb = (p0[j + 1] - p0[j]).norm();
    if (la < me || lb < me) continue;
    // Eq. 3.7 linearised with the input's edge lengths, multiplied by la·lb:
    // lb·(P_j − P_{j−1}) − la·(P_{j+1} − P_j) = 0.
    for (int x = 0; x < 3; ++x) {
      const int r = static_cast<int>(d.size());
      row(3 * j + x, lb + la, r);
      row(3 * (j - 1) + x, -lb, r);
      row(3 * (j + 1) + x, -la, r);
      d.push_back(0.0);
    }
  }
  for (const PointTarget& pt : pr.points)
    for (int x = 0; x < 3; ++x) {
      row(3 * pt.index + x, 1.0, static_cast<int>(d.size()));
      d.push_back(pt.target[x]);
    }
  if (pr.closure)
    for (int x = 0; x < 3; ++x) {
      const int r = static_cast<int>(d.size());
      row(x, 1.0, r);
      row(3 * (m - 1) + x, -1.0, r);
      d.push_back(0.0);
    }

  const int nc = static_cast<int>(d.size());
  const Eigen::VectorXd dv = Eigen::Map<const Eigen::VectorXd>(d.data(), nc);
  const KktMethod method =
      pr.method != KktMethod::automatic ? pr.method
      : nc >= kSparseLuRows             ? KktMethod::sparse_lu
                                        : KktMethod::range_space;
  const std::optional<Eigen::VectorXd> solved =
      method == KktMethod::sparse_lu ? solve_sparse_lu(a, c, rhs, dv) : solve_range_space(a, c, rhs, dv);
  if (!solved) return res;
  const Eigen::VectorXd& x = *solved;

  res.control_points.resize(m);
  for (int i = 0; i < m; ++i) res.control_points[i] = x.segment<3>(3 * i);
  for (const PointTarget& pt : pr.points) {
    res.control_points[pt.index] = pt.target;  // exact: removes the last ulp of drift
  }
  if (pr.closure) {
    res.control_points[m - 1] = res.control_points[0];
  }
  for (const PointTarget& pt : pr.points)
    res.max_constraint_residual =
        std::max(res.max_constraint_residual, (x.segment<3>(3 * pt.index) - pt.target).norm());
  if (pr.closure)
    res.max_constraint_residual = std::max(
        res.max_constraint_residual, (x.segment<3>(0) - x.segment<3>(3 * (m - 1))).norm());
  res.fidelity = fidelity_energy(p0, res.control_points, me, pr.fidelity);
  // A residual far above rounding means the targets were inconsistent.
  res.ok = std::isfinite(res.fidelity) && res.max_constraint_residual < 1e-7;
  return res;
}

}  // namespace sketchlab::cassie
