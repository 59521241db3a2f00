#include "cassie_params.hpp"

namespace sketchlab::cassie {

std::vector<ParamSpec> param_specs() {
  const CassieParams d;
  const double pi = std::numbers::pi;
  return {
      {"delta", ParamType::real, d.delta, 0.001, 0.5, {}, "m",
       "small distance δ at zoom 1 (thesis §3.2.3.1: 0.02); thresholds are δ/s"},
      {"angle", ParamType::real, d.angle, 0.01, pi / 2, {}, "rad",
       "angular threshold θ for tangents, axis planes and axis lines (π/6)"},
      {"proximity", ParamType::real, d.proximity_factor, 0.1, 10.0, {}, "δ",
       "intersection detection radius r_detect (thesis §3.2.3.2: 2δ)"},
      {"reuse", ParamType::real, d.reuse_factor, 0.0, 5.0, {}, "δ",
       "reuse an existing control point within this distance instead of splitting (eq. 3.3: δ)"},
      {"mirror_snap", ParamType::real, d.mirror_factor, 0.0, 10.0, {}, "δ",
       "project stroke endpoints this close onto the mirror plane (public source: 1.25δ)"},
      {"surface_snap", ParamType::real, d.surface_factor, 0.0, 10.0, {}, "δ",
       "on-surface proximity (thesis §3.3.5 says 2δ; public source 2.5δ)"},
      {"lambda", ParamType::real, d.lambda, 0.0, 1.0, {}, "",
       "fidelity weight λ in E = λ·E_fidelity + (1−λ)·E_connectivity (CHI §4.3: 0.6)"},
      {"weight_grid", ParamType::real, d.weight_grid, 0.0, 100.0, {}, "",
       "connectivity weight of a grid node or the mirror plane along the stroke (CHI eq. 3: 1)"},
      {"weight_grid_endpoint", ParamType::real, d.weight_grid_endpoint, 0.0, 100.0, {}, "",
       "connectivity weight of a grid node at a stroke endpoint (CHI eq. 3: 1.25)"},
      {"weight_curve", ParamType::real, d.weight_curve, 0.0, 100.0, {}, "",
       "connectivity weight of another curve (CHI eq. 3: 1.5)"},
      {"weight_node", ParamType::real, d.weight_node, 0.0, 100.0, {}, "",
       "connectivity weight of an existing intersection (CHI eq. 3: 2)"},
      {"weight_closure", ParamType::real, d.weight_closure, 0.0, 100.0, {}, "",
       "connectivity weight of closing the stroke on itself (not in the paper: as a curve)"},
      {"tangent_weight", ParamType::real, d.tangent_weight, 0.0, 1e6, {}, "",
       "multiplier of E_tangent (eq. 3.8, normalised by the edge length)"},
      {"planarity_weight", ParamType::real, d.planarity_weight, 0.0, 1e6, {}, "",
       "multiplier of E_planar (eq. 3.9, normalised like the fidelity slope term)"},
      {"planarity", ParamType::boolean, d.planarity, {}, {}, {}, "", "planarity soft constraint"},
      {"tangents", ParamType::boolean, d.tangents, {}, {}, {}, "",
       "tangent alignment soft constraints at intersections"},
      {"line_axis_snap", ParamType::boolean, d.line_axis_snap, {}, {}, {}, "",
       "align lines within θ of an axis to it (Appendix A.1)"},
      {"on_surface", ParamType::boolean, d.on_surface, {}, {}, {}, "",
       "project strokes drawn on a patch onto it (thesis §3.3.5)"},
      {"max_candidates", ParamType::integer, std::int64_t{d.max_candidates}, 1.0, 64.0, {}, "",
       "at most this many candidate intersections (the closest) enter the greedy search"},
      {"mirror", ParamType::choice, std::string("workspace"), {}, {}, {"workspace", "plane", "off"},
       "",
       "workspace: snap to the mirror plane and add the mirrored copy (paper); plane: snap only "
       "(replaying imported CASSIE sessions, which record both twins); off: ignore the mirror"},
      {"fit_error", ParamType::real, d.preprocess.fit_error_factor, 0.01, 5.0, {}, "δ",
       "poly-Bézier fitting tolerance (public source: 0.5δ)"},
      {"sharp_angle", ParamType::real, d.preprocess.max_g1_angle, 0.05, pi / 2, {}, "rad",
       "tangent turn above which a joint is sharp (CHI §4.4: 45°)"},
      {"detect_lines", ParamType::boolean, d.preprocess.detect_lines, {}, {}, {}, "",
       "fit straight strokes with a line (thesis §3.2.2)"},
      {"remove_hooks", ParamType::boolean, d.preprocess.remove_hooks, {}, {}, {}, "",
       "cut hooks at both ends of the stroke (thesis §3.2.2)"},
  };
}

CassieParams params_from(const Params& p) {
  CassieParams c;
  c.delta = p.real("delta");
  c.angle = p.real("angle");
  c.proximity_factor = p.real("proximity");
  c.reuse_factor = p.real("reuse");
  c.mirror_factor = p.real("mirror_snap");
  c.surface_factor = p.real("surface_snap");
  c.lambda = p.real("lambda");
  c.weight_grid = p.real("weight_grid");
  c.weight_grid_endpoint = p.real("weight_grid_endpoint");
  c.weight_curve = p.real("weight_curve");
  c.weight_node = p.real("weight_node");
  c.weight_closure = p.real("weight_closure");
  c.tangent_weight = p.real("tangent_weight");
  c.planarity_weight = p.real("planarity_weight");
  c.planarity = p.boolean("planarity");
  c.tangents = p.boolean("tangents");
  c.line_axis_snap = p.boolean("line_axis_snap");
  c.on_surface = p.boolean("on_surface");
  c.max_candidates = static_cast<int>(p.integer("max_candidates"));
  const std::string& m = p.string("mirror");
  c.mirror = m == "off" ? MirrorMode::off : m == "plane" ? MirrorMode::plane : MirrorMode::workspace;
  c.preprocess.delta = c.delta;
  c.preprocess.fit_error_factor = p.real("fit_error");
  c.preprocess.max_g1_angle = p.real("sharp_angle");
  c.preprocess.detect_lines = p.boolean("detect_lines");
  c.preprocess.remove_hooks = p.boolean("remove_hooks");
  return c;
}

}  // namespace sketchlab::cassie
