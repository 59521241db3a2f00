#pragma once
// What the grid evaluation needs from an implicit surface model: f and ∇f at
// a point. Both the global Hermite RBF (hermite_interpolant.hpp) and the
// partition of unity of local fits (partition_of_unity.hpp) provide it.
#include "sketchlab/types.hpp"

namespace sketchlab::hermite_rbf {

class ImplicitFunction {
 public:
  virtual ~ImplicitFunction() = default;
  // f(x) in metres (x in metres); f < 0 inside, f = 0 on the surface, and
  // ∇f (unitless) equals the constrained normals there.
  virtual double value(const Vec3& x) const = 0;
  // f and ∇f together. Returns exactly the same f as value(x).
  virtual double value_gradient(const Vec3& x, Vec3& gradient) const = 0;
};

// A ball of space (where a changing function changed, e.g.).
struct Sphere {
  Vec3 center = Vec3::Zero();  // m
  double radius = 0.0;         // m
};

}  // namespace sketchlab::hermite_rbf
