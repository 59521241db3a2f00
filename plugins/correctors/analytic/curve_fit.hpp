#pragma once
// Fitting a cubic Hermite/Bézier spline with fixed joints to the rays through
// a stroke's samples (Schmidt et al. 2009 §3.2 eq. 6), by the foot-point
// method: with the sample parameters fixed the problem is linear least
// squares in the curve variables (solved with Eigen), then each sample's
// curve parameter moves to the point of its segment nearest to its ray.
// Hard constraints are enforced by reparametrisation: a tangent with a known
// direction d is α·d (one variable), a planar tangent a·e1 + b·e2, and a
// mirror-symmetric curve takes its second half's tangents from the first.
#include <optional>
#include <vector>

#include "sketchlab/curve.hpp"
#include "sketchlab/view.hpp"

namespace sketchlab::analytic {

struct FitProblem {
  std::vector<Vec3> joints;                      // n >= 2 fixed positions, in order
  std::vector<std::optional<Vec3>> tangent_dir;  // per joint: unit direction or free
  std::optional<Vec3> plane_normal;              // planar: free tangents in the plane
  bool symmetric = false;  // mirror plane ⟂ (last - first) through their midpoint
  // Rays of the stroke samples of each segment (n-1 lists), with initial
  // local parameters in (0, 1).
  std::vector<std::vector<Ray>> rays;
  std::vector<std::vector<double>> u0;
};

struct FitResult {
  Curve curve;             // 3(n-1)+1 control points
  double residual = 0.0;   // RMS ray distance, metres
  bool ok = false;
  std::vector<std::vector<double>> u;  // final sample parameters (warm starts)
};

FitResult fit_spline(const FitProblem& problem, int iterations);

}  // namespace sketchlab::analytic
