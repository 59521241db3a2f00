#include "analytic_params.hpp"

namespace sketchlab::analytic {

std::vector<ParamSpec> parameter_specs() {
  const AnalyticParams d;
  using T = ParamType;
  return {
      {"v_max", T::real, d.v_max, 1.0, 1000.0, {}, "in/s", "pen speed of the widest uncertainty radius, §3.1 eq. 3 (40 in/s)"},
      {"delta_min", T::real, d.delta_min, 0.001, 5.0, {}, "in", "uncertainty radius of a slow pen, §3.1 eq. 3 (0.1 in)"},
      {"delta_max", T::real, d.delta_max, 0.001, 5.0, {}, "in", "uncertainty radius of a fast pen, §3.1 eq. 3 (0.5 in)"},
      {"collect_factor", T::real, d.collect_factor, 0.5, 10.0, {}, "δ", "constraints are collected within this many δ of the stroke (2)"},
      {"direction_spread", T::real, d.direction_spread / degrees, 0.1, 90.0, {}, "deg", "r_d = 1 − cos(this), §3.1 eq. 4 (10°)"},
      {"perturbation_samples", T::integer, std::int64_t{d.perturbation_samples}, 1, 100000, {}, "", "perturbed strokes voting for the segment, §3.1 (hundreds; 200)"},
      {"seed", T::integer, static_cast<std::int64_t>(d.seed), 0, 2147483647.0, {}, "", "seed of the perturbation sampling"},
      {"f_vertex", T::real, d.f_vertex, 0.0, 100.0, {}, "", "eq. 5 f(C°) at a scaffold vertex (paper: hand-tuned, 1)"},
      {"f_intersection", T::real, d.f_intersection, 0.0, 100.0, {}, "", "eq. 5 f(C°) at a guideline/line intersection (1)"},
      {"f_on_line", T::real, d.f_on_line, 0.0, 100.0, {}, "", "eq. 5 f(C°) for the nearest point on a line (0.5)"},
      {"f_curve_intersection", T::real, d.f_curve_intersection, 0.0, 100.0, {}, "", "eq. 5 f(C°) where the stroke crosses a curve's projection (1, as f_intersection)"},
      {"f_vanishing", T::real, d.f_vanishing, 0.0, 100.0, {}, "", "eq. 5 f(Cᵈ) along an existing vanishing direction (1)"},
      {"f_through", T::real, d.f_through, 0.0, 100.0, {}, "", "eq. 5 f(Cᵈ) through a scaffold vertex (1)"},
      {"f_perpendicular", T::real, d.f_perpendicular, 0.0, 100.0, {}, "", "eq. 5 f(Cᵈ) perpendicular to a line at the start (0.8)"},
      {"f_dist_point", T::real, d.f_dist_point, 0.0, 100.0, {}, "", "eq. 5 f(Cᵗ) ending on a position constraint (1)"},
      {"f_dist_free", T::real, d.f_dist_free, 0.0, 100.0, {}, "", "eq. 5 f(Cᵗ) ending at the nearest point to the stroke (0.5)"},
      {"k_r", T::real, d.k_r, 0.1, 20.0, {}, "", "curve uncertainty factor, §3.2 eq. 7 (2)"},
      {"f_planar", T::real, d.f_planar, 0.0, 100.0, {}, "", "§3.2 planarity constant (1.5)"},
      {"f_symmetric", T::real, d.f_symmetric, 0.0, 100.0, {}, "", "§3.2 symmetry constant (1.1)"},
      {"f_tangent_point", T::real, d.f_tangent_point, 0.0, 100.0, {}, "", "§3.2 point with a tangent constraint (1.5)"},
      {"f_point", T::real, d.f_point, 0.0, 100.0, {}, "", "§3.2 point without tangent constraint (1.1)"},
      {"lambda", T::real, d.lambda, 0.0, 10.0, {}, "", "§3.2 normalisation (1 + λe^{−λ(n−2)}) (0.25)"},
      {"r_kappa", T::real, d.r_kappa, 0.01, 100.0, {}, "", "§3.2 eq. 8 curvature spread r_κ (2)"},
      {"max_curve_points", T::integer, std::int64_t{d.max_curve_points}, 2, 22, {}, "", "position constraints considered per curve stroke"},
      {"fit_iterations", T::integer, std::int64_t{d.fit_iterations}, 0, 200, {}, "", "foot-point rounds of the eq. 6 fit"},
      {"samples_per_segment", T::integer, std::int64_t{d.samples_per_segment}, 2, 200, {}, "", "stroke rays per spline segment in the eq. 6 fit"},
      {"score_samples", T::integer, std::int64_t{d.score_samples}, 2, 10000, {}, "", "N of eq. 7"},
      {"curve_g_slack", T::real, d.curve_g_slack, 0.0, 100.0, {}, "", "curve branch-and-bound: G <= min(1, slack·G(free fit)); 0 = the paper's G <= 1 (choice, 2)"},
      {"curve_exhaustive", T::boolean, d.curve_exhaustive, {}, {}, {}, "", "fit every curve constraint combination (no branch-and-bound)"},
      {"straightness", T::real, d.straightness, 0.0, 1.0, {}, "", "straight stroke: chord deviation below this fraction of the chord (and δ_max)"},
      {"ellipse_snap", T::boolean, d.ellipse_snap, {}, {}, {}, "", "snap a planar curve close to an elliptic arc onto it, §3.2"},
      {"ellipse_tolerance", T::real, d.ellipse_tolerance, 0.0, 1.0, {}, "", "elliptic-arc snap: largest deviation / major semi-axis (1 %)"},
      {"guideline_angle", T::real, d.guideline_angle / degrees, 0.0, 45.0, {}, "deg", "guideline stroke within this angle of a vanishing direction, §2.2 (3°)"},
      {"tick_length", T::real, d.tick_length, 0.0, 10.0, {}, "in", "dimension ticks are shorter than this, §2.3 (0.4 in)"},
      {"reinfer_free", T::boolean, d.reinfer_free, {}, {}, {}, "", "re-infer free strokes near new geometry, §2.1"},
  };
}

AnalyticParams params_from(const Params& p) {
  AnalyticParams a;
  a.v_max = p.real("v_max");
  a.delta_min = p.real("delta_min");
  a.delta_max = p.real("delta_max");
  a.collect_factor = p.real("collect_factor");
  a.direction_spread = p.real("direction_spread") * degrees;
  a.perturbation_samples = static_cast<int>(p.integer("perturbation_samples"));
  a.seed = static_cast<std::uint64_t>(p.integer("seed"));
  a.f_vertex = p.real("f_vertex");
  a.f_intersection = p.real("f_intersection");
  a.f_on_line = p.real("f_on_line");
  a.f_curve_intersection = p.real("f_curve_intersection");
  a.f_vanishing = p.real("f_vanishing");
  a.f_through = p.real("f_through");
  a.f_perpendicular = p.real("f_perpendicular");
  a.f_dist_point = p.real("f_dist_point");
  a.f_dist_free = p.real("f_dist_free");
  a.k_r = p.real("k_r");
  a.f_planar = p.real("f_planar");
  a.f_symmetric = p.real("f_symmetric");
  a.f_tangent_point = p.real("f_tangent_point");
  a.f_point = p.real("f_point");
  a.lambda = p.real("lambda");
  a.r_kappa = p.real("r_kappa");
  a.max_curve_points = static_cast<int>(p.integer("max_curve_points"));
  a.fit_iterations = static_cast<int>(p.integer("fit_iterations"));
  a.samples_per_segment = static_cast<int>(p.integer("samples_per_segment"));
  a.score_samples = static_cast<int>(p.integer("score_samples"));
  a.curve_g_slack = p.real("curve_g_slack");
  a.curve_exhaustive = p.boolean("curve_exhaustive");
  a.straightness = p.real("straightness");
  a.ellipse_snap = p.boolean("ellipse_snap");
  a.ellipse_tolerance = p.real("ellipse_tolerance");
  a.guideline_angle = p.real("guideline_angle") * degrees;
  a.tick_length = p.real("tick_length");
  a.reinfer_free = p.boolean("reinfer_free");
  return a;
}

}  // namespace sketchlab::analytic
