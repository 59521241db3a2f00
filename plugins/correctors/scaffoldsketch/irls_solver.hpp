#pragma once
// Iteratively re-weighted least squares over a scaffold line's two endpoints
// (ScaffoldSketch §4.1, eq. 6–7).
#include <vector>

#include "scaffold_candidates.hpp"

namespace sketchlab::scaffoldsketch {

struct IrlsOptions {
  double point_point_weight = 100.0;  // initial weight of point–point terms
  double other_weight = 1.0;          // initial weight of the others
  double epsilon = 1e-12;             // ε of eq. 7; C <= ε counts as satisfied
  int max_iterations = 50;            // IRLS rounds
  double move_tolerance = 1e-7;       // m: endpoints moving less than this are settled (0.1·sqrt(ε))
  // Only direction terms kept (they leave the length free): true keeps the
  // drawn length about the midpoint, false the nearest line to the input.
  bool direction_only_keeps_length = true;
};

struct IrlsResult {
  Vec3 a = Vec3::Zero(), b = Vec3::Zero();  // solved endpoints
  int iterations = 0;         // IRLS rounds (re-solves of eq. 6)
  int solver_steps = 0;       // Levenberg–Marquardt steps, polish included
  bool converged = false;     // the satisfied set and the endpoints settled
  std::vector<double> weights;   // per term: the last IRLS weight (eq. 7)
  std::vector<double> energies;  // per term: C_i at the result
  std::vector<bool> enforced;    // per term: satisfied (C_i <= ε) at the result
};

// Minimises Σ w_i C_i(l) (eq. 6) from (a, b) in place with Levenberg–
// Marquardt on the residuals of term_residual, plus μ·(|a−a0|² + |b−b0|²)
// with μ = anchor_ratio · (largest diagonal entry of JᵀWJ at the start),
// at least 1e-6 (1/m²). Eq. 6 alone leaves the directions its terms do not
// constrain free (a line with a snapped end and level terms may turn about
// that end, one with only direction terms may stretch); the anchor holds
// them where the user drew them, and moves a satisfied term by about
// anchor_ratio times the distance to the input. Returns the number of steps.
int minimise_weighted(const std::vector<ScaffoldTerm>& terms, const std::vector<double>& weights,
                      Vec3& a, Vec3& b, const Vec3& a0, const Vec3& b0,
                      double anchor_ratio = 1e-12, int max_steps = 200);

// IRLS: weights start at w0_i / (ε + C_i(l_input)) with w0 = 100 for
// point–point and 1 otherwise (the input line is iteration 0 of eq. 7, which
// breaks the symmetry of exactly conflicting terms in favour of what the
// user drew), then each round solves eq. 6 and sets w_i = 1 / (ε + C_i(l)).
// It stops when the set of satisfied terms (C_i <= ε) and the endpoints stop
// changing. The limit of the weights is binary (∞ satisfied, 0 discarded), so
// a final solve with the discarded terms' weights set to 0 makes the
// satisfied ones exact; then, in every direction the satisfied terms leave
// free, the line is moved back to where it was drawn (the nearest line to
// the input that satisfies them; with direction_only_keeps_length, a line
// whose satisfied terms are all directions also gets its drawn length back,
// which they do not change). Never returns NaN: a non-finite or
// collapsed solution falls back to the input line with nothing enforced.
IrlsResult solve_irls(const std::vector<ScaffoldTerm>& terms, const Vec3& a0, const Vec3& b0,
                      const IrlsOptions& options);

}  // namespace sketchlab::scaffoldsketch
