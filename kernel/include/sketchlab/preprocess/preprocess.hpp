#pragma once
// Stroke preprocessing shared by all correctors (CASSIE thesis §3.2.2):
// hook removal, line detection, and otherwise RDP simplification followed by
// a G1 poly-Bézier fit with sharp corners. Defaults are CASSIE's (public
// source; see data/cassie/README.md). Every distance threshold is a multiple
// of δ and scales as δ(s) = δ/s with the workspace zoom s.
#include <numbers>
#include <string>
#include <vector>

#include "sketchlab/curve.hpp"
#include "sketchlab/preprocess/hooks.hpp"
#include "sketchlab/stroke.hpp"

namespace sketchlab {

struct PreprocessParams {
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
};

// Empty when every parameter is in range, else "name = value: allowed range".
std::string validate(const PreprocessParams& params);

struct Preprocessed {
  std::vector<Vec3> points;  // input points within `kept` (hooks cut)
  IndexRange kept;           // indices of the input kept
  bool is_line = false;
  Curve curve;  // make_line(first, last kept point) for lines, else the fit
};

// Runs the pipeline on points (metres in workspace space) with times
// (seconds; same size, non-decreasing, or empty if unknown) drawn at zoom
// workspace_scale > 0. The fitted curve (non-line case) lies within
// (fit_error_factor + rdp_epsilon_factor)·δ/s of every kept point. Throws
// std::invalid_argument naming the problem for fewer than 2 points,
// zero-length strokes, non-finite input, mismatched times or invalid params.
Preprocessed preprocess_stroke(const std::vector<Vec3>& points, const std::vector<double>& times,
                               const PreprocessParams& params, double workspace_scale);

// Same on a stroke's sample positions, times and workspace_scale; errors
// name the stroke id.
Preprocessed preprocess_stroke(const Stroke& stroke, const PreprocessParams& params = {});

}  // namespace sketchlab
