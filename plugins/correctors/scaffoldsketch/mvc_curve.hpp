#pragma once
// Minimum-variation-of-curvature piecewise Bézier through keypoints with
// fixed tangent directions (ScaffoldSketch §4.2.2, eq. 8–9).
#include <string>
#include <vector>

#include "scaffold_params.hpp"
#include "sketchlab/curve.hpp"

namespace sketchlab::scaffoldsketch {

// Menger curvature of three points (eq. 8): 4·area / product of the side
// lengths, 1/m. 0 for collinear or coincident points. When `grad` is given,
// also its gradient with respect to (a, b, c) (3 x 3, one column per point).
double menger_curvature(const Vec3& a, const Vec3& b, const Vec3& c, Mat3* grad = nullptr);

// Curvature (1/m) of the circle through q tangent to the unit direction d
// that passes through b: 2|d × (b − q)| / |b − q|², the limit of eq. 8 for
// (q − h·d, q, b) as h → 0. 0 when b = q or b lies on the tangent line. With
// `grad`, also its gradient with respect to b.
double tangent_curvature(const Vec3& q, const Vec3& d, const Vec3& b, Vec3* grad = nullptr);

struct MvcResult {
  Curve curve;                      // K = m-1 cubic segments through Q
  std::vector<double> magnitudes;   // x_{k,1}, x_{k,2} per segment (metres)
  double objective = 0.0;           // eq. 9 at the result (1/m²)
  double initial_objective = 0.0;   // eq. 9 at x = chord/3
  int evaluations = 0;              // objective + gradient evaluations
  int rounds = 0;                   // optimisations run (resampling in between)
  std::string status;               // NLopt result of the last round
};

// Segment k joins q_k and q_{k+1} with inner control points q_k + x_{k,1} d_k
// and q_{k+1} - x_{k,2} d_{k+1}; x starts at |q_{k+1} - q_k| / 3 and is kept
// in [1e-3, 3]·chord (no cusps, no loops). The objective is eq. 9 over
// Menger curvatures (eq. 8) of samples uniform in arclength, about
// samples_per_segment per segment on average and at least 2 per segment,
// and with params.tangent_curvature, at each keypoint, the tangent_curvature
// toward the sample before and the one after (without them a turn inside the
// first sample interval is invisible to eq. 9, and shrinking a handle to
// its bound leaves a hook: issue #18). Sample parameters are fixed during a
// solve (so the gradient is exact) and re-spread by arclength on the
// solution for a second solve. Minimised with
// NLopt LD_LBFGS and analytic gradients. `closed`: q.front() == q.back() and
// curvature is compared across the seam. Requires m >= 2 points (distinct
// neighbours) and unit tangents; throws std::invalid_argument otherwise.
MvcResult fit_mvc_curve(const std::vector<Vec3>& q, const std::vector<Vec3>& d, bool closed,
                        const ShapeParams& params);

}  // namespace sketchlab::scaffoldsketch
