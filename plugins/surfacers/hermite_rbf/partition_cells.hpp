#pragma once
// The cells of the partition of unity (Ohtake, Belyaev, Alexa, Turk & Seidel
// 2003, "Multi-level partition of unity implicits", §3): an octree over the
// domain, each cell with a support sphere of radius overlap × its half
// diagonal (Ohtake: 0.75 × the diagonal, i.e. overlap 1.5), split while the
// support holds more than max_rows rows. A leaf whose support holds too little
// to fit a surface fits the constraints of a larger sphere (Ohtake §3: "the
// support radius is enlarged until it contains at least N_min points"),
// here until it holds min_rows rows and min_normals normal constraints, so no
// local fit is the trivial f ≡ 0 of points and tangents alone. Unlike
// Ohtake's, its weight keeps the cell's own support: the enlarged fit reaches
// the data for the shape it extrapolates, without being summed (and paid for)
// all the way out there. The blend stays exact, since every constraint inside
// the weight's support is among the fit's.
#include <cstddef>
#include <vector>

#include "hermite_constraints.hpp"
#include "hermite_rbf_params.hpp"

namespace sketchlab::hermite_rbf {

// Constraints addressed by one flat index: points [0, P), tangents [P, P+T),
// normals [P+T, P+T+N) of a HermiteConstraints.
struct ConstraintIndex {
  std::size_t points = 0, tangents = 0, normals = 0;
  explicit ConstraintIndex(const HermiteConstraints& c)
      : points(c.points.size()), tangents(c.tangents.size()), normals(c.normals.size()) {}
  std::size_t size() const { return points + tangents + normals; }
  bool is_normal(std::size_t k) const { return k >= points + tangents; }
  int rows(std::size_t k) const { return is_normal(k) ? 3 : 1; }
  const Vec3& position(const HermiteConstraints& c, std::size_t k) const {
    if (k < points) return c.points[k];
    if (k < points + tangents) return c.tangent_points[k - points];
    return c.normal_points[k - points - tangents];
  }
};

struct PartitionCell {
  Vec3 center = Vec3::Zero();  // m, centre of the octree cell and of its spheres
  double half_edge = 0.0;      // m, of the octree cell
  double radius = 0.0;         // m, support of the weight (overlap × the cell's half diagonal)
  double fit_radius = 0.0;     // m, sphere whose constraints the local fit meets (>= radius)
  int depth = 0;
  // Flat indices (ConstraintIndex) of every constraint with ‖x − center‖ <
  // fit_radius, ascending. The local fit interpolates exactly these, so the
  // blend meets every constraint (a weight is > 0 exactly inside `radius`).
  std::vector<std::size_t> members;
  int rows = 0;                // rows of the members (1 per point or tangent, 3 per normal)
};

// The leaves of the octree over the cube around `domain` (m), depth-first
// order. A pure function of its arguments: the same constraints in the same
// order give the same cells whatever was computed before (the incremental
// update relies on it).
std::vector<PartitionCell> partition_cells(const HermiteConstraints& constraints, const Box3& domain,
                                           const PartitionParams& params);

}  // namespace sketchlab::hermite_rbf
