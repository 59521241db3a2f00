#pragma once
// Stroke preprocessing shared by all correctors (CASSIE thesis §3.2.2):
// hook removal, line detection, and otherwise RDP simplification followed by
// a G1 poly-Bézier fit with sharp corners. Defaults are CASSIE's (public
// source; see data/cassie/README.md). Every distance threshold is a multiple
// of δ and scales as δ(s) = δ/s with the workspace zoom s.
#include <array>
#include <numbers>
#include <string>
#include <vector>

#include "sketchlab/curve.hpp"
#include "sketchlab/preprocess/hooks.hpp"
#include "sketchlab/stroke.hpp"

namespace sketchlab {

// Which reading of CASSIE's preprocessing to run.
enum class PreprocessRules {
  // Thesis §3.2.2 with sketchlab's choices where it gives no numbers: hooks
  // as C1 discontinuities measured at two scales (hooks.hpp), lines by length
  // ratio and speed (detect_line), corners on a δ window (fit_poly_bezier).
  sketchlab,
  // The CASSIE app (reference items 1–4, cassie-original-behaviour.md):
  // input filtering (input_filter.hpp), the line test first on the raw
  // samples (detect_line_by_excess), hooks and corners from sample turns
  // (find_hookless_range_by_turns, find_corners_by_turns), each section
  // simplified by RDP and fitted by Schneider's method with two-point
  // tangents, 20 reparameterisations under 10× the tolerance and the fixed
  // 0.01 split tolerance.
  cassie_app,
};

struct PreprocessParams {
  PreprocessRules rules = PreprocessRules::sketchlab;
  double delta = 0.02;             // m: CASSIE's small distance δ at zoom 1
  double fit_error_factor = 0.5;   // ×δ: Bézier fitting tolerance
  double max_g1_angle = std::numbers::pi / 4;  // rad: max turn inside a G1 section
  bool remove_hooks = true;
  double hook_max_length_factor = 3.0;   // ×δ: a hook spans at most 3δ ...
  double hook_max_fraction = 0.15;       // ... and 15 % of the stroke length
  double hook_min_length_factor = 0.5;   // ×δ: shorter turns are noise
  double hook_min_angle = std::numbers::pi / 4;  // rad: turn that makes a hook
  bool detect_lines = true;
  double line_min_length_ratio = 0.98;  // chord / length (see line_detection.hpp)
  double line_min_speed = 0.2;          // m/s of hand motion at zoom 1; 0 disables
  double rdp_epsilon_factor = 0.1;      // ×δ: RDP tolerance (2 mm, as CASSIE's export)
  double corner_window_factor = 1.0;    // ×δ: scale at which corners are measured
  double tangent_window_factor = 0.5;   // ×δ: scale at which end tangents are measured
  // cassie_app rules only (the app's values); fit_error_factor,
  // max_g1_angle (corners), hook_max_length_factor, hook_max_fraction and
  // rdp_epsilon_factor above apply to both.
  bool app_filter_input = true;              // item 1 (off: the samples are already the app's)
  double app_sample_step_factor = 0.1;       // ×δ: a sample when the hand moved more (item 1)
  double app_min_length_factor = 0.5;        // ×δ: shorter strokes are dropped (item 1)
  double app_min_duration = 0.2;             // s: briefer strokes with ends < 0.5δ apart are dropped
  double app_end_trim = 0.02;                // s: samples this close to either end are removed
  // Item 1 keeps both end samples. Set, the stroke ends app_end_trim of hand
  // motion before its last sample (at the hand's mean speed over its last
  // 0.1 s; the samples beyond dropped): CASSIE's structured curves end there
  // (plugin cassie, README "Where this differs from the reference"); its
  // Freehand system ends at the last sample.
  bool app_trim_last_end = false;
  double app_line_time = 0.05;               // s: a line is faster than δ per this time (item 2)
  double app_hook_angle = std::numbers::pi / 6;  // rad: turn that cuts a hook (item 3)
  TurnSpan app_hook_turn = TurnSpan::consecutive;  // how that turn is measured (turns.hpp)
  int app_corner_min_samples = 4;            // a corner bounds sections of at least this many samples
  double app_corner_min_length_factor = 1.0;  // ×δ ... longer than this (item 4)
  int app_reparameterizations = 20;          // Schneider rounds (item 4)
  double app_reparameterize_below = 10.0;    // ... when the error is under this × the tolerance
  double app_split_tolerance = 0.01;         // m, not scaled with zoom: the app's quirk (item 4)
};

// The CASSIE app's preprocessing (rules cassie_app) with its parameters.
PreprocessParams cassie_app_preprocess();

// Empty when every parameter is in range, else "name = value: allowed range".
std::string validate(const PreprocessParams& params);

struct Preprocessed {
  std::vector<Vec3> points;  // the points fitted: input within `kept` (hooks cut; cassie_app: filtered)
  // Indices of the input of the first and last point kept (app_trim_last_end:
  // the last point lies between input kept.last and the next).
  IndexRange kept;
  bool is_line = false;
  std::array<bool, 2> hook_cut{false, false};  // a hook was cut at the start / end
  Curve curve;  // make_line(first, last kept point) for lines, else the fit
};

// Runs the pipeline on points (metres in workspace space) with times
// (seconds; same size, non-decreasing, or empty if unknown) drawn at zoom
// workspace_scale > 0. The fitted curve (non-line case) passes within about
// (fit_error_factor + rdp_epsilon_factor)·δ/s of every kept point and never
// leaves their neighbourhood (tests/kernel/preprocess: two-sided distance
// over every bundled stroke). Throws std::invalid_argument naming the
// problem for fewer than 2 points, zero-length strokes, non-finite input,
// mismatched times or invalid params, and (cassie_app) for a stroke the app
// drops ("dropped as the CASSIE app does: ...").
Preprocessed preprocess_stroke(const std::vector<Vec3>& points, const std::vector<double>& times,
                               const PreprocessParams& params, double workspace_scale);

// Same on a stroke's sample positions, times and workspace_scale; errors
// name the stroke id.
Preprocessed preprocess_stroke(const Stroke& stroke, const PreprocessParams& params = {});

}  // namespace sketchlab
