#pragma once
// CASSIE structuring parameters. Defaults are the original CASSIE app's
// (../shared/reference/cassie-original-behaviour.md, "CASSIE app, item N"),
// which agree with the papers (CHI 2021 §4.4, thesis §3.2.3.1, Appendix A,
// §3.3.5) where those give numbers. Distances are at zoom 1 and scale as
// δ(s) = δ/s; factors are multiples of δ(s).
#include <numbers>
#include <string>
#include <vector>

#include "sketchlab/plugin/params.hpp"
#include "sketchlab/preprocess/preprocess.hpp"

namespace sketchlab::cassie {

// What to do with the workspace mirror plane.
enum class MirrorMode {
  workspace,  // paper: constrain to the plane and add the mirrored copy
  plane,      // constrain to the plane only (imported sessions record both twins)
  off,        // ignore the mirror plane
};

// When a constraint at an existing node aligns the tangents (item 11: "at a
// node where tangents point the same way").
enum class NodeAlignment {
  opposite,  // the curves' parametric tangents point opposite ways (CASSIE's logs, see README)
  same,      // they point the same way
};

// Normalisation of E_fidelity.
enum class FidelityNorm {
  cassie_app,  // item 13: 0.5/N·Σ|d|²/(2δ)² + 0.5/(N−1)·Σ|Δd|²/|e₀|²
  thesis,      // thesis eq. 3.2: 1/(N·L²)·Σ|d|² + 1/(N−1)·Σ|Δd|²/|e₀|²
};

// What E_connectivity's weights are divided by.
enum class ConnectivityTotal {
  cassie_app,  // item 13: the constraints that got an anchor
  thesis,      // thesis eq. 3.12: every detected constraint
};

// Which plane item 14's 2δ planarity test measures the control points
// against.
enum class PlanarityTest {
  fitted,   // the least-squares plane, snapped to an axis afterwards (CHI §4.2; CASSIE's `planar` flags)
  snapped,  // the plane after its normal was snapped to an axis
};

// Item 20: what counts as the brush colliding with a patch. brush: a raw
// hand position within the brush radius of the patch's mesh while touching
// no curve's collider (a curve, not the patch, is then the brush's main
// collider: item 6); control_points: a control point within surface_snap.
enum class SurfaceTouch { brush, control_points };

// Item 20's "the patch spans it", which the reference leaves open. box: the
// patch's bounding box, grown by max_distance, holds every control point;
// stroke_ends: also the stroke's first and last hand positions are within
// the brush radius of the mesh; brush: also every hand position away from the
// curves (on_surface.hpp's `SurfaceBrush::away`) is (README, "CASSIE's patches in the rebuild").
enum class SurfaceSpan { box, stroke_ends, brush };

// Items 1–4 as CASSIE structures a stroke: the app's preprocessing
// (cassie_app_preprocess) with the last end trimmed by item 1's 0.02 s, as
// its curves show (README, "Where this differs from the reference").
PreprocessParams cassie_structuring_preprocess();

struct CassieParams {
  double delta = 0.02;                   // m, δ at zoom 1 (thesis §3.2.3.1)
  double angle = std::numbers::pi / 6;   // rad, θ (thesis §3.2.3.1)
  // Detection while drawing (item 6): the brush sphere, stepped in time,
  // against the collider tubes of the curves.
  double brush_factor = 1.0;             // ×δ, radius of the brush sphere (see README: the app's 2δ is its diameter)
  double proximity_factor = 2.0;         // ×δ, r_detect (thesis §3.2.3.2): grid, line snap, planarity
  double collider_radius = 0.0015;       // m, tube around each curve (not scaled)
  double brush_step = 0.02;              // s, physics step of the brush test
  double merge_factor = 0.5;             // ×δ, consecutive constraints this close are one (item 7)
  double plane_merge_factor = 1.0;       // ×δ, two plane constraints this close are one
  // Constraints (items 8, 11, 12).
  double reuse_factor = 1.0;             // ×δ, reuse an anchor within δ (item 12)
  double node_snap_factor = 1.0;         // ×δ, snap to an end node of the crossed piece (item 8)
  double dangling_snap_factor = 1.0;     // ×δ, join the crossed curve's lone end node (item 22)
  double correction_factor = 0.5;        // ×δ, targets tried on the old curve: ±δ/2
  int correction_points = 6;             // ... this many
  bool correction_keeps_target = false;  // ... and the detected target itself (a second reading, README)
  bool corrected_node_snap = true;       // item 8's node snap again at the corrected target
  double weight_grid = 1.0;              // grid point and mirror plane (CHI eq. 3: 1)
  double weight_endpoint = 1.25;         // at least this within δ of a stroke end (item 11)
  double weight_curve = 1.5;
  double weight_node = 2.0;
  double tangent_bonus = 0.5;            // added to the weight of an aligned constraint
  NodeAlignment node_alignment = NodeAlignment::opposite;
  double lambda = 0.6;                   // fidelity vs connectivity (CHI eq. 2)
  FidelityNorm fidelity = FidelityNorm::cassie_app;
  double position_scale = 2.0;           // δ: cassie_app's position term over (this·δ)² (item 13: 2)
  ConnectivityTotal connectivity = ConnectivityTotal::cassie_app;
  double tangent_weight = 2.0;           // E_tangent = w/|e₀|²·|T×e|² (item 14: 2)
  double planarity_weight = 1.0;         // E_planar multiplier (item 14: 1)
  bool planarity = true;
  PlanarityTest planarity_test = PlanarityTest::fitted;
  bool tangents = true;
  // Stroke ends (items 9, 10, 16).
  bool overlap_cut = true;               // item 9
  double overlap_factor = 2.0;           // ×δ
  double closure_factor = 2.0;           // ×δ, ends this close close the stroke (item 10)
  bool trim_dangling = true;             // item 16
  double trim_fraction = 0.15;           // a dangling piece under 15 % of the length ...
  double trim_factor = 3.0;              // ... and 3δ is cut
  int max_solver_segments = 10;          // item 5: longer strokes are not constrained (0: no limit)
  // Lines (item 17).
  bool line_axis_snap = true;
  double line_keep_factor = 0.2;         // ×δ: one of two constraints this close; node within this
  // Mirror (item 18) and surfaces (item 20).
  double mirror_factor = 1.25;           // ×δ, whole-stroke projection onto the mirror plane
  double mirror_on_plane_factor = 0.1;   // ×δ, an intersection "on the plane"
  double surface_factor = 2.5;           // ×δ, control points projected onto a patch
  bool on_surface = true;
  SurfaceTouch surface_touch = SurfaceTouch::brush;
  SurfaceSpan surface_span = SurfaceSpan::brush;
  MirrorMode mirror = MirrorMode::workspace;
  PreprocessParams preprocess = cassie_structuring_preprocess();  // items 1–4
  double input_spacing_factor = 0.0;     // ×δ, densify the samples first (input_density.hpp; 0: off)
  // With the reference's own decisions (parameter `oracle`, a file the
  // plugin reads: constraint_oracle.hpp), how close (×δ) one of our targets
  // must be to one it applied to count as it: δ/2, the distance items 7
  // (merge) and 8 (correction) move or merge a target by.
  double oracle_radius_factor = 0.5;
  bool oracle_positions = false;  // ... and is enforced at the applied target's position, not ours
};

// Thresholds of one stroke: the factors above times δ(s) = δ/s.
struct Thresholds {
  double delta = 0.02;
  double brush = 0.02;      // brush radius
  double contact = 0.0215;  // brush radius + collider tube
  double proximity = 0.04;  // r_detect
  double grid = 0.04;       // grid points within this of a sample (item 19: 2δ)
  double merge = 0.01;
  double plane_merge = 0.02;
  double reuse = 0.02;
  double node_snap = 0.02;
  double dangling_snap = 0.02;
  double correction = 0.01;
  double overlap = 0.04;
  double closure = 0.04;
  double trim = 0.06;
  double line_keep = 0.004;
  double mirror = 0.025;
  double on_plane = 0.002;
  double surface = 0.05;
  double oracle = 0.01;
};
Thresholds thresholds(const CassieParams& p, double workspace_scale);

std::vector<ParamSpec> param_specs();
CassieParams params_from(const Params& p);

}  // namespace sketchlab::cassie
