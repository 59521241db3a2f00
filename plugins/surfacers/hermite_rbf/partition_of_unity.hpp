#pragma once
// The partition-of-unity implicit (Ohtake, Belyaev, Alexa, Turk & Seidel
// 2003, "Multi-level partition of unity implicits", Eq. 1) over local
// Hermite RBF fits (Macêdo, Gois & Velho 2011):
//
//   f(x) = Σ_i w_i(x) f_i(x) / Σ_i w_i(x),   w_i(x) = ψ(‖x − c_i‖ / R_i),
//   ψ(t) = (1 − t)⁴ (4t + 1) for t < 1, 0 beyond (Wendland 1995, ψ_{3,1}: C², compact),
//
// where f_i is the exact Hermite RBF (hermite_interpolant.hpp) of every
// constraint inside cell i's fit sphere, which contains its weight's support
// sphere (c_i, R_i) (partition_cells.hpp). Every f_i whose weight is non-zero
// at a constraint meets it, so the blend meets it too: f = Σ w_i·0 / Σ w_i = 0, and with every f_i = 0 there,
// ∇f = Σ (w_i ∇f_i + f_i ∇w_i) / Σ w_i − f ∇(Σ w_i) / Σ w_i = n.
// Cost: each fit is a dense solve of at most max_rows rows (linear memory and
// time in the constraints), each evaluation sums the few fits around x.
#include <cstdint>
#include <memory>
#include <vector>

#include "hermite_interpolant.hpp"
#include "partition_cells.hpp"

namespace sketchlab::hermite_rbf {

struct PartitionReport {
  std::size_t cells = 0;
  std::size_t cells_fitted = 0;  // solved now; the others were reused from the previous model
  int max_rows = 0;              // rows of the largest local system
  double mean_rows = 0.0;
  double regularizer = 0.0;      // the largest λ a local solve needed
  // Supports whose fit changed (new cells, and cells of the previous model no
  // longer present): f may differ from the previous model only inside them.
  std::vector<Sphere> changed;
};

class PartitionOfUnity final : public ImplicitFunction {
 public:
  double value(const Vec3& x) const override;
  double value_gradient(const Vec3& x, Vec3& gradient) const override;
  const std::vector<PartitionCell>& cells() const { return cells_; }
  const HermiteInterpolant& fit(std::size_t cell) const { return *fits_[cell]; }

 private:
  friend PartitionOfUnity fit_partition_of_unity(const HermiteConstraints&, const Box3&, const PartitionParams&,
                                                 const SolveParams&, int, PartitionReport&, const PartitionOfUnity*);
  template <bool gradient>
  double evaluate(const Vec3& x, Vec3* g) const;
  void build_lookup(const Box3& domain);

  std::shared_ptr<const HermiteConstraints> constraints_;  // what the cells' members index
  std::vector<PartitionCell> cells_;
  std::vector<std::shared_ptr<const HermiteInterpolant>> fits_;  // shared with the model they were reused from
  std::vector<double> regularizers_;                         // λ of each fit
  std::vector<std::uint64_t> keys_;                          // hash of each cell's centre, spheres and members
  // Uniform buckets over the domain listing the cells whose support meets each (CSR).
  Vec3 lookup_origin_ = Vec3::Zero();
  double bucket_ = 1.0;
  int buckets_ = 1;
  std::vector<std::uint32_t> bucket_start_, bucket_cells_;
};

// Decomposes, fits every cell (in parallel over `threads`, 0 = all cores; the
// result does not depend on it) and builds the evaluation lookup. With
// `previous`, cells equal to one of its cells (same centre, spheres and member
// constraints, compared by value) reuse its fit: the result is identical to a
// fit from scratch, and only the changed supports are reported. Throws
// std::invalid_argument on degenerate input (check_constraints),
// std::runtime_error when a local system stays singular.
PartitionOfUnity fit_partition_of_unity(const HermiteConstraints& constraints, const Box3& domain,
                                        const PartitionParams& params, const SolveParams& solve, int threads,
                                        PartitionReport& report, const PartitionOfUnity* previous = nullptr);

}  // namespace sketchlab::hermite_rbf
