#pragma once
// Parameters of the analytic-drawing corrector (Schmidt et al. 2009). Lengths
// on the input surface are inches (converted to pixels with View::dpi, §3.1),
// angles radians, 3D lengths metres.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "sketchlab/plugin/params.hpp"

namespace sketchlab::analytic {

inline constexpr double degrees = std::numbers::pi / 180.0;

struct AnalyticParams {
  // §3.1 eq. 3: δ_i = Lerp(v_i / v_max, δ_min, δ_max).
  double v_max = 40.0;     // in/s
  double delta_min = 0.1;  // in
  double delta_max = 0.5;  // in
  // Constraints are collected within this multiple of δ of the stroke (§3.1:
  // "we collect all potential constraints within δ"; the Gaussian of eq. 3 is
  // still 2% at 2δ, so the default reaches 2δ).
  double collect_factor = 2.0;
  // §3.1 eq. 4: r_d = 1 - cos(10°).
  double direction_spread = 10.0 * degrees;
  // §3.1 "hundreds of sampled strokes".
  int perturbation_samples = 200;
  // §3.1: each perturbed endpoint is "a uniform Gaussian with a deviation
  // defined by our uncertainty radius δ"; per-axis deviation in units of δ.
  double perturbation_deviation = 0.7071067811865476;
  std::uint64_t seed = 1;
  // Hand-tuned constants f of eq. 5 (paper: Figure 7, values not given).
  double f_vertex = 1.0;        // C°: scaffold vertex (a)
  double f_intersection = 1.0;  // C°: guideline / line intersection (b, c)
  double f_on_line = 0.5;       // C°: nearest point on a guideline or line (d)
  double f_curve_intersection = 1.0;  // C°: stroke crosses a curve's projection (c)
  // Cᵈ: existing vanishing direction (h). Above f_through: a segment between
  // two points placed by eye stays on the vanishing direction it nearly
  // follows (§4.1–4.2 / Fig. 11: nearly-parallel directions propagate; README).
  double f_vanishing = 2.0;
  double f_through = 1.0;       // Cᵈ: line through a scaffold vertex (e, f)
  double f_perpendicular = 0.8; // Cᵈ: perpendicular direction (g)
  double f_dist_point = 1.0;    // Cᵗ: ends on a position constraint
  double f_dist_free = 0.5;     // Cᵗ: nearest point along the projected direction
  // §3.2 curve constants.
  double k_r = 2.0;            // eq. 7
  double f_planar = 1.5;
  double f_symmetric = 1.1;
  double f_tangent_point = 1.5;
  double f_point = 1.1;
  double lambda = 0.25;        // normalisation (1 + λ e^{-λ(n-2)})
  double r_kappa = 2.0;        // eq. 8
  int max_curve_points = 12;   // position constraints considered per curve stroke
  int fit_iterations = 6;     // foot-point rounds (eq. 6)
  int samples_per_segment = 8;
  int score_samples = 64;      // N of eq. 7
  // Branch-and-bound on curves (§3.2). The paper bounds G by 1; eq. 8's G is
  // set by the stroke's shape (0.11 for a two-turn helix), so a point set's
  // G is bounded by min(1, curve_g_slack · G(free fit)) instead. Not strictly
  // admissible; <= 0 restores the paper's G <= 1.
  double curve_g_slack = 2.0;
  // Fit every combination (no pruning): the reference for the bound.
  bool curve_exhaustive = false;
  // A stroke is straight when its largest deviation from the chord is below
  // this fraction of the chord (and below δ_max).
  double straightness = 0.04;
  // Elliptic-arc snap: largest deviation, as a fraction of the arc's size.
  double ellipse_tolerance = 0.01;
  bool ellipse_snap = true;
  // Guidelines: stroke direction within this angle of a vanishing direction.
  double guideline_angle = 3.0 * degrees;
  // ... or its end within this many δ of the vanishing line through its
  // known point (§3.1 eq. 3; 2 like collect_factor, seventh round).
  double guideline_reach = 2.0;
  // Among vanishing directions passing those tests, take the one with the
  // best §3.1 fitness of the segment {known point, direction, free end}
  // (eq. 3 × eq. 4) instead of the smallest angle (eighth round).
  bool guideline_fitness = true;
  // §2: "the first stroke is assumed to lie in the ground plane" (Fig. 3a):
  // the first scaffold stroke becomes the ground-plane segment between its
  // ends even when it fails the straightness test; false = only a straight
  // one, a curved first stroke left free (ninth round of the tablet sessions).
  bool first_stroke_ground = false;
  // A segment within this angle of an existing vanishing direction adds no
  // vanishing direction of its own (§4.2: nearly-parallel vanishing directions,
  // Fig. 11d; the paper suggests "automatic filtering").
  double vanishing_merge = std::acos(0.99999);
  // Dimension ticks: straight strokes shorter than this (in) crossing a guideline.
  double tick_length = 0.4;
  // A tick crosses a guideline whose projection passes within tick_reach·δ
  // beyond either end (§3.1's uncertainty radius; 0 = the drawn tick only).
  double tick_reach = 1.0;
  bool reinfer_free = true;
  // Hook removal before inference (not in the paper; kernel's
  // find_hookless_range): a turn of 45° or more within hook_max_length of an
  // end (and 15 % of the stroke), not closer than hook_min_length, is cut.
  bool remove_hooks = true;
  double hook_max_length = 0.3;   // in
  double hook_min_length = 0.025; // in
  // A hook is a straight flick: its outer and inner halves turn by at most
  // this fraction of the turn at the cut (HookParams::max_bend_ratio), so a
  // curve's own tight bend near an end (a flat ellipse's tip) is kept.
  double hook_max_bend = 0.2;
};

std::vector<ParamSpec> parameter_specs();
AnalyticParams params_from(const Params& p);

}  // namespace sketchlab::analytic
