#include "analytic_params.hpp"

#include "sketchlab/plugin/param_table.hpp"

namespace sketchlab::analytic {

namespace {
const ParamTable<AnalyticParams>& parameters() {
  using A = AnalyticParams;
  static const auto table = ParamTable<A>()
      .real("v_max", &A::v_max, 1.0, 1000.0, "in/s", "pen speed of the widest uncertainty radius, §3.1 eq. 3 (40 in/s)")
      .real("delta_min", &A::delta_min, 0.001, 5.0, "in", "uncertainty radius of a slow pen, §3.1 eq. 3 (0.1 in)")
      .real("delta_max", &A::delta_max, 0.001, 5.0, "in", "uncertainty radius of a fast pen, §3.1 eq. 3 (0.5 in)")
      .real("collect_factor", &A::collect_factor, 0.5, 10.0, "δ", "constraints are collected within this many δ of the stroke (2)")
      .real("direction_spread", &A::direction_spread, 0.1, 90.0, "deg", "r_d = 1 − cos(this), §3.1 eq. 4 (10°)", degrees)
      .integer("perturbation_samples", &A::perturbation_samples, 1, 100000, "", "perturbed strokes voting for the segment, §3.1 (hundreds; 200)")
      .real("perturbation_deviation", &A::perturbation_deviation, 0.01, 10.0, "δ", "per-axis deviation of a perturbed stroke end, §3.1 (1/√2: the variance of eq. 3's kernel)")
      .integer("seed", &A::seed, 0, 2147483647.0, "", "seed of the perturbation sampling")
      .real("f_vertex", &A::f_vertex, 0.0, 100.0, "", "eq. 5 f(C°) at a scaffold vertex (paper: hand-tuned, 1)")
      .real("f_intersection", &A::f_intersection, 0.0, 100.0, "", "eq. 5 f(C°) at a guideline/line intersection (1)")
      .real("f_on_line", &A::f_on_line, 0.0, 100.0, "", "eq. 5 f(C°) for the nearest point on a line (0.5)")
      .real("f_curve_intersection", &A::f_curve_intersection, 0.0, 100.0, "", "eq. 5 f(C°) where the stroke crosses a curve's projection (1, as f_intersection)")
      .real("f_vanishing", &A::f_vanishing, 0.0, 100.0, "", "eq. 5 f(Cᵈ) along an existing vanishing direction (2)")
      .real("f_through", &A::f_through, 0.0, 100.0, "", "eq. 5 f(Cᵈ) through a scaffold vertex (1)")
      .real("f_perpendicular", &A::f_perpendicular, 0.0, 100.0, "", "eq. 5 f(Cᵈ) perpendicular to a line at the start (0.8)")
      .real("f_dist_point", &A::f_dist_point, 0.0, 100.0, "", "eq. 5 f(Cᵗ) ending on a position constraint (1)")
      .real("f_dist_free", &A::f_dist_free, 0.0, 100.0, "", "eq. 5 f(Cᵗ) ending at the nearest point to the stroke (0.5)")
      .real("k_r", &A::k_r, 0.1, 20.0, "", "curve uncertainty factor, §3.2 eq. 7 (2)")
      .real("f_planar", &A::f_planar, 0.0, 100.0, "", "§3.2 planarity constant (1.5)")
      .real("f_symmetric", &A::f_symmetric, 0.0, 100.0, "", "§3.2 symmetry constant (1.1)")
      .real("f_tangent_point", &A::f_tangent_point, 0.0, 100.0, "", "§3.2 point with a tangent constraint (1.5)")
      .real("f_point", &A::f_point, 0.0, 100.0, "", "§3.2 point without tangent constraint (1.1)")
      .real("lambda", &A::lambda, 0.0, 10.0, "", "§3.2 normalisation (1 + λe^{−λ(n−2)}) (0.25)")
      .real("r_kappa", &A::r_kappa, 0.01, 100.0, "", "§3.2 eq. 8 curvature spread r_κ (2)")
      .integer("max_curve_points", &A::max_curve_points, 2, 22, "", "position constraints considered per curve stroke")
      .integer("fit_iterations", &A::fit_iterations, 0, 200, "", "foot-point rounds of the eq. 6 fit")
      .integer("samples_per_segment", &A::samples_per_segment, 2, 200, "", "stroke rays per spline segment in the eq. 6 fit")
      .integer("score_samples", &A::score_samples, 2, 10000, "", "N of eq. 7")
      .real("curve_g_slack", &A::curve_g_slack, 0.0, 100.0, "", "curve branch-and-bound: G <= min(1, slack·G(free fit)); 0 = the paper's G <= 1 (choice, 2)")
      .boolean("curve_exhaustive", &A::curve_exhaustive, "fit every curve constraint combination (no branch-and-bound)")
      .real("straightness", &A::straightness, 0.0, 1.0, "", "straight stroke: chord deviation below this fraction of the chord (and δ_max)")
      .boolean("ellipse_snap", &A::ellipse_snap, "snap a planar curve close to an elliptic arc onto it, §3.2")
      .real("ellipse_tolerance", &A::ellipse_tolerance, 0.0, 1.0, "", "elliptic-arc snap: largest deviation / major semi-axis (1 %)")
      .real("guideline_angle", &A::guideline_angle, 0.0, 45.0, "deg", "guideline stroke within this angle of a vanishing direction, §2.2 (3°)", degrees)
      .real("guideline_reach", &A::guideline_reach, 0.0, 10.0, "δ", "or its end within this many δ of the vanishing line, §3.1 eq. 3 (choice, 2)")
      .boolean("guideline_fitness", &A::guideline_fitness, "choose a guideline's direction by eq. 3 × eq. 4 of the segment {known point, direction, free end}, §3.1 (choice, on); off = the smallest angle")
      .boolean("first_stroke_ground", &A::first_stroke_ground, "the first scaffold stroke lies in the ground plane (§2, Fig. 3a) even when not straight; off = only a straight one")
      .real("vanishing_merge", &A::vanishing_merge, 0.0, 45.0, "deg", "a segment within this angle of a vanishing direction adds no new one, §4.1–4.2 / Fig. 11d (0.26°)", degrees)
      .real("tick_length", &A::tick_length, 0.0, 10.0, "in", "dimension ticks are shorter than this, §2.3 (0.4 in)")
      .real("tick_reach", &A::tick_reach, 0.0, 10.0, "δ", "a tick crosses a guideline passing within this many δ beyond its ends, §3.1 eq. 3 (1)")
      .boolean("reinfer_free", &A::reinfer_free, "re-infer free strokes near new geometry, §2.1")
      .boolean("remove_hooks", &A::remove_hooks, "cut a hook (a sharp flick) at either end of a stroke before inference (not in the paper)")
      .real("hook_max_length", &A::hook_max_length, 0.001, 10.0, "in", "a hook spans at most this distance from its end (0.3 in)")
      .real("hook_min_length", &A::hook_min_length, 0.0, 10.0, "in", "turns closer than this to an end are jitter, not hooks (0.025 in)")
      .real("hook_max_bend", &A::hook_max_bend, 0.0, 1.0, "",
            "a hook is straight: its halves turn by at most this fraction of the turn at the cut (0.2; at 1 a hook may bend as much as it turns)");
  return table;
}
}  // namespace

std::vector<ParamSpec> parameter_specs() { return parameters().specs(); }

AnalyticParams params_from(const Params& p) { return parameters().read(p); }

}  // namespace sketchlab::analytic
