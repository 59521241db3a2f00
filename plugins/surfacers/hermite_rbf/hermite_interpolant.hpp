#pragma once
// The Hermite RBF interpolant (Macêdo, Gois & Velho 2011, cited as [BMS*10]
// in JustDrawIt §6) with φ(r) = r³ and a linear polynomial:
//
//   f(x) = Σ_c [ α_c φ(‖x − x_c‖) − β_c · ∇φ(x − x_c) ] + a₀ + a·x,
//
// where ∇φ(v) = 3‖v‖v. Each value constraint f(x_k) = 0 adds α at x_k; each
// directional constraint d·∇f(x_k) = b (tangent: d = t, b = 0; normal: d =
// e_x, e_y, e_z, b = n) adds a coefficient times d to β at x_k. The
// coefficients solve the symmetric system [A P; Pᵀ 0] with A_kl = λ_k λ_l φ,
// P_k = λ_k(1, x, y, z).
#include <string>
#include <vector>

#include "hermite_constraints.hpp"
#include "hermite_rbf_params.hpp"
#include "implicit_function.hpp"

namespace sketchlab::hermite_rbf {

// Centres as separate arrays (normalised coordinates).
struct RbfCenters {
  std::vector<double> x, y, z;      // position
  std::vector<double> alpha;        // value coefficient
  std::vector<double> bx, by, bz;   // β, the directional coefficients
  std::size_t size() const { return x.size(); }
  void add(const Vec3& p) {
    x.push_back(p.x()), y.push_back(p.y()), z.push_back(p.z());
    alpha.push_back(0.0), bx.push_back(0.0), by.push_back(0.0), bz.push_back(0.0);
  }
};

// Evaluates in metres: f(x) = scale · f̂((x − origin) / scale), so f vanishes
// on the constraint points and ∇f equals the normals there.
struct HermiteInterpolant final : ImplicitFunction {
  RbfCenters centers;
  double a0 = 0.0;
  Vec3 a = Vec3::Zero();
  Vec3 origin = Vec3::Zero();  // m
  double scale = 1.0;          // m (the normalisation length, e.g. the constraints' bounding-box diagonal)

  double value(const Vec3& x) const override;
  double value_gradient(const Vec3& x, Vec3& gradient) const override;

 private:
  template <bool gradient>
  double evaluate(const Vec3& x, Vec3* g) const;
};

struct SolveReport {
  std::size_t unknowns = 0;  // rows of the kernel block (+ 4 polynomial terms)
  int polynomial_rank = 0;   // rank of P (4 unless every constraint lies on a plane with in-plane directions)
  double regularizer = 0.0;  // λ actually used (normalised units)
  double solve_ms = 0.0;
  // Worst violations, evaluated on the interpolant: |f| at points (m),
  // ‖∇f − n‖ at normals, |∇f·t| at tangents.
  double residual_point = 0.0, residual_normal = 0.0, residual_tangent = 0.0;
};

// The exact global fit: every constraint in one dense system, in coordinates
// normalised to the constraints' bounding box (centre, diagonal). O(m²)
// memory and O(m³) time for m rows; the reference the partition of unity is
// tested against. Throws std::invalid_argument on degenerate input (no normal
// constraint, fewer than 3 distinct points, collinear points).
HermiteInterpolant fit_hermite_rbf(const HermiteConstraints& constraints, const SolveParams& params,
                                   SolveReport& report);

// Builds and solves the system in coordinates (x − origin) / scale: the
// polynomial is eliminated with a QR of P (null-space method), leaving the
// symmetric positive definite Qᵀ(A + λI)Q (φ = r³ is conditionally positive
// definite of order 2), factored with Cholesky (LLT); λ is multiplied by 100
// until the factorisation succeeds. A rank-deficient P (constraints on a line
// or a plane) is handled by the rank-revealing QR. No input validation beyond
// "at least one row left after the polynomial" (std::invalid_argument);
// std::runtime_error when the system stays singular. Does not fill residuals.
HermiteInterpolant solve_hermite_rbf(const HermiteConstraints& constraints, const Vec3& origin, double scale,
                                     const SolveParams& params, SolveReport& report);

// Fills the residual fields of `report` with f's violations of `constraints`.
void measure_residuals(const ImplicitFunction& f, const HermiteConstraints& constraints, SolveReport& report);

}  // namespace sketchlab::hermite_rbf
