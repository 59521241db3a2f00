#pragma once
// Curve inference (Schmidt et al. 2009 §3.2): position and tangent
// constraints from the scaffold near a stroke, every combination of them
// scored by F = S·G·C (eq. 7, 8 and the constants of §3.2), with
// branch-and-bound on the upper bound S_free·G_bound·C so that most
// combinations are never fitted.
#include <optional>
#include <vector>

#include "analytic_params.hpp"
#include "sketchlab/camera.hpp"
#include "scaffold.hpp"
#include "stroke_2d.hpp"

namespace sketchlab::analytic {

struct CurvePoint {
  Vec3 p = Vec3::Zero();
  double arclength = 0.0;        // pixels along the stroke of its nearest point
  std::vector<Vec3> directions;  // tangent options: directions of lines through p
  std::vector<int> lines;        // the scaffold lines giving them
};

struct CurveCombination {
  std::vector<int> points;    // indices into CurvePoint list, in stroke order
  std::vector<int> tangents;  // per chosen point: -1 free, else index into directions
  bool planar = false;
  bool symmetric = false;
  double weight = 0.0;  // C
};

struct CurveChoice {
  CurveCombination combination;
  Curve curve;
  double fitness = 0.0, s = 0.0, g = 0.0;
};

struct CurveInference {
  std::vector<CurvePoint> points;
  std::optional<CurveChoice> best, runner_up;
  double confidence = 0.0;        // F(runner-up) / F(best)
  long long combinations = 0;     // generated
  long long fitted = 0;           // curves actually fitted
  // Fitted curves whose G exceeded their family's G bound (curve_g_slack):
  // evidence of that bound not being admissible on this stroke.
  long long g_bound_exceeded = 0;
  bool snapped_to_ellipse = false;
};

// Position constraints (scaffold vertices, line intersections) whose
// projection is within k_r·δ of the stroke, ordered along it.
std::vector<CurvePoint> collect_curve_points(const Scaffold& scaffold, const Camera& camera,
                                             const Stroke2d& stroke, const AnalyticParams& p);

// Eq. 7: mean over N curve samples of G(d_s(c_j), k_r δ_j).
double curve_stroke_score(const Curve& curve, const Camera& camera, const Stroke2d& stroke,
                          const AnalyticParams& p);
// Eq. 8: G(∫|κ|dt / κ_opt − 1, r_κ), κ_opt = π t_max / arclength.
double curvature_prior(const Curve& curve, const AnalyticParams& p);
// §3.2: product of the constants, normalised by (1 + λ e^{−λ(n−2)}).
double combination_weight(const CurveCombination& c, const AnalyticParams& p);

CurveInference infer_curve(const Scaffold& scaffold, const Camera& camera, const Stroke2d& stroke,
                           const AnalyticParams& p);

}  // namespace sketchlab::analytic
