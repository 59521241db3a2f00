#pragma once
// CASSIE structuring parameters (CHI 2021 §4.4, thesis §3.2.3.1, Appendix A,
// §3.3.5) with the defaults of the papers and of CASSIE's public source
// (data/cassie/README.md). Distances are at zoom 1 and scale as δ(s) = δ/s.
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

struct CassieParams {
  double delta = 0.02;                        // m, δ at zoom 1 (thesis §3.2.3.1)
  double angle = std::numbers::pi / 6;        // rad, θ (thesis §3.2.3.1)
  double proximity_factor = 2.0;              // ×δ, r_detect = 2δ (thesis §3.2.3.2)
  double reuse_factor = 1.0;                  // ×δ, reuse a control point within δ (eq. 3.3–3.4)
  double mirror_factor = 1.25;                // ×δ, endpoint projection onto the mirror plane
  double surface_factor = 2.5;                // ×δ, on-surface proximity (public source)
  double lambda = 0.6;                        // fidelity vs connectivity (CHI eq. 2)
  double weight_grid = 1.0;                   // CHI eq. 3 weights
  double weight_grid_endpoint = 1.25;
  double weight_curve = 1.5;
  double weight_node = 2.0;
  double weight_closure = 1.5;                // not in the paper: a self-intersection
  double tangent_weight = 1.0;                // E_tangent multiplier (eq. 3.8)
  double planarity_weight = 1.0;              // E_planar multiplier (eq. 3.9)
  bool planarity = true;
  bool tangents = true;
  bool line_axis_snap = true;                 // Appendix A.1
  bool on_surface = true;                     // thesis §3.3.5
  int max_candidates = 12;                    // cap on detected intersections (closest kept)
  MirrorMode mirror = MirrorMode::workspace;
  PreprocessParams preprocess;                // hooks, lines, RDP, G1 fit (thesis §3.2.2)
};

std::vector<ParamSpec> param_specs();
CassieParams params_from(const Params& p);

}  // namespace sketchlab::cassie
