#include "cassie_params.hpp"

#include "sketchlab/workspace.hpp"

namespace sketchlab::cassie {

Thresholds thresholds(const CassieParams& p, double s) {
  Thresholds t;
  t.delta = scaled_threshold(p.delta, s);
  t.brush = p.brush_factor * t.delta;
  t.contact = t.brush + p.collider_radius;
  t.proximity = p.proximity_factor * t.delta;
  t.grid = t.proximity;
  t.merge = p.merge_factor * t.delta;
  t.plane_merge = p.plane_merge_factor * t.delta;
  t.reuse = p.reuse_factor * t.delta;
  t.node_snap = p.node_snap_factor * t.delta;
  t.correction = p.correction_factor * t.delta;
  t.overlap = p.overlap_factor * t.delta;
  t.closure = p.closure_factor * t.delta;
  t.trim = p.trim_factor * t.delta;
  t.line_keep = p.line_keep_factor * t.delta;
  t.mirror = p.mirror_factor * t.delta;
  t.on_plane = p.mirror_on_plane_factor * t.delta;
  t.surface = p.surface_factor * t.delta;
  return t;
}

std::vector<ParamSpec> param_specs() {
  const CassieParams d;
  const double pi = std::numbers::pi;
  auto real = [](const char* name, double def, double lo, double hi, const char* unit, const char* doc) {
    return ParamSpec{name, ParamType::real, def, lo, hi, {}, unit, doc};
  };
  auto flag = [](const char* name, bool def, const char* doc) {
    return ParamSpec{name, ParamType::boolean, def, {}, {}, {}, "", doc};
  };
  return {
      real("delta", d.delta, 0.001, 0.5, "m",
           "small distance δ at zoom 1 (thesis §3.2.3.1: 0.02); thresholds are δ/s"),
      real("angle", d.angle, 0.01, pi / 2, "rad",
           "angular threshold θ for tangents, overlaps, axis planes and axis lines (π/6)"),
      real("brush", d.brush_factor, 0.1, 10.0, "δ",
           "radius of the brush sphere that detects curves and the mirror plane while drawing "
           "(item 6 gives 2δ, the sphere's diameter: the app's logs cut off at δ + 1.5 mm)"),
      real("proximity", d.proximity_factor, 0.1, 10.0, "δ",
           "r_detect (thesis §3.2.3.2: 2δ): grid points (item 19), line end snaps (item 17), planarity "
           "(item 14)"),
      real("collider_radius", d.collider_radius, 0.0, 0.1, "m",
           "radius of the collider tube around each curve (item 6: 1.5 mm, not scaled)"),
      real("brush_step", d.brush_step, 0.001, 1.0, "s",
           "time step at which the brush is tested (item 6: the 0.02 s physics step)"),
      real("merge", d.merge_factor, 0.0, 5.0, "δ",
           "a constraint this close to the previous one replaces or is dropped for it (item 7: δ/2)"),
      real("plane_merge", d.plane_merge_factor, 0.0, 5.0, "δ",
           "two consecutive mirror-plane constraints this close are one (item 7: δ)"),
      real("reuse", d.reuse_factor, 0.0, 5.0, "δ",
           "a constraint within this of an anchor of its Bézier reuses it, else splits (item 12: δ)"),
      real("node_snap", d.node_snap_factor, 0.0, 5.0, "δ",
           "a target snaps to an end node (two incidences or more) of the crossed piece within this "
           "(item 8: δ)"),
      real("correction", d.correction_factor, 0.0, 5.0, "δ",
           "targets tried on the old curve around the detected one, ± this (item 8: δ/2)"),
      {"correction_points", ParamType::integer, std::int64_t{d.correction_points}, 0.0, 64.0, {}, "",
       "how many targets are tried on the old curve (item 8: 6; 0 keeps the detected target)"},
      real("weight_grid", d.weight_grid, 0.0, 100.0, "",
           "connectivity weight of a grid point or the mirror plane (CHI eq. 3: 1)"),
      real("weight_endpoint", d.weight_endpoint, 0.0, 100.0, "",
           "weight at least this for a constraint within δ of a stroke end (item 11: 1.25)"),
      real("weight_curve", d.weight_curve, 0.0, 100.0, "",
           "connectivity weight of another curve (CHI eq. 3: 1.5)"),
      real("weight_node", d.weight_node, 0.0, 100.0, "",
           "connectivity weight of an existing intersection (CHI eq. 3: 2)"),
      real("tangent_bonus", d.tangent_bonus, 0.0, 100.0, "",
           "added to the weight of a constraint whose tangents align (item 11: 0.5)"),
      real("lambda", d.lambda, 0.0, 1.0, "",
           "fidelity weight λ in E = λ·E_fidelity + (1−λ)·E_connectivity (CHI §4.3: 0.6)"),
      {"fidelity", ParamType::choice, std::string("cassie_app"), {}, {}, {"cassie_app", "thesis"}, "",
       "E_fidelity normalisation: cassie_app (item 13: positions over (2δ)², halves) or thesis "
       "(eq. 3.2: positions over the stroke span L²)"},
      real("tangent_weight", d.tangent_weight, 0.0, 1e6, "",
           "E_tangent = w/|e₀|²·|T×e|² on the edge at an aligned constraint (item 14: 2)"),
      real("planarity_weight", d.planarity_weight, 0.0, 1e6, "",
           "E_planar multiplier, (1/(N−1))·Σ(n·e)²/|e₀|² (item 14: 1)"),
      flag("planarity", d.planarity, "planarity soft constraint (item 14)"),
      flag("tangents", d.tangents, "tangent alignment soft constraints at intersections (item 14)"),
      flag("overlap_cut", d.overlap_cut,
           "cut a stroke end that runs along the curve it meets (item 9)"),
      real("overlap", d.overlap_factor, 0.0, 10.0, "δ",
           "an end constraint this close to the stroke end may cut the overlap (item 9: 2δ)"),
      real("closure", d.closure_factor, 0.0, 10.0, "δ",
           "a poly-Bézier whose ends are this close is closed, a hard constraint (item 10: 2δ)"),
      flag("trim_dangling", d.trim_dangling,
           "cut the short piece beyond the first/last enforced intersection (item 16)"),
      real("trim_fraction", d.trim_fraction, 0.0, 1.0, "",
           "dangling pieces under this fraction of the length ... (item 16: 0.15)"),
      real("trim", d.trim_factor, 0.0, 20.0, "δ", "... and under this length are cut (item 16: 3δ)"),
      {"max_solver_segments", ParamType::integer, std::int64_t{d.max_solver_segments}, 0.0, 1e6, {}, "",
       "poly-Béziers with more segments are returned unconstrained (item 5: 10; 0: no limit)"},
      flag("line_axis_snap", d.line_axis_snap, "align lines within θ of an axis to it (item 17)"),
      real("line_keep", d.line_keep_factor, 0.0, 5.0, "δ",
           "of two line constraints this close one is kept; a node needs the line this close "
           "(item 17: 0.2δ)"),
      real("mirror_snap", d.mirror_factor, 0.0, 10.0, "δ",
           "project the whole stroke onto the mirror plane within this (item 18: 1.25δ)"),
      real("mirror_on_plane", d.mirror_on_plane_factor, 0.0, 10.0, "δ",
           "an intersection this close to the mirror plane is on it (item 18: 0.1δ)"),
      real("surface_snap", d.surface_factor, 0.0, 10.0, "δ",
           "project control points this close onto a patch (item 20: 2.5δ; thesis text 2δ)"),
      flag("on_surface", d.on_surface, "project strokes drawn on a patch onto it (item 20)"),
      {"mirror", ParamType::choice, std::string("workspace"), {}, {}, {"workspace", "plane", "off"},
       "",
       "workspace: snap to the mirror plane and add the mirrored copy (paper); plane: snap only "
       "(replaying imported CASSIE sessions, which record both twins); off: ignore the mirror"},
      {"preprocess", ParamType::choice, std::string("cassie_app"), {}, {}, {"cassie_app", "sketchlab"}, "",
       "cassie_app: the app's input filtering, line test, hooks, corners and fit (items 1-4); "
       "sketchlab: the thesis §3.2.2 reading (kernel preprocess.hpp)"},
      flag("filter_input", d.preprocess.app_filter_input,
           "drop samples closer than 0.1δ, strokes too short or brief, samples of the first and last "
           "0.02 s (item 1; cassie_app preprocessing)"),
      real("fit_error", d.preprocess.fit_error_factor, 0.01, 5.0, "δ",
           "poly-Bézier fitting tolerance (item 4: 0.5δ)"),
      real("sharp_angle", d.preprocess.max_g1_angle, 0.05, pi, "rad",
           "direction turn above which a sample is a corner (item 4: π/4)"),
      flag("detect_lines", d.preprocess.detect_lines, "fit straight strokes with a line (item 2)"),
      flag("remove_hooks", d.preprocess.remove_hooks, "cut hooks at both ends of the stroke (item 3)"),
  };
}

CassieParams params_from(const Params& p) {
  CassieParams c;
  c.delta = p.real("delta");
  c.angle = p.real("angle");
  c.brush_factor = p.real("brush");
  c.proximity_factor = p.real("proximity");
  c.collider_radius = p.real("collider_radius");
  c.brush_step = p.real("brush_step");
  c.merge_factor = p.real("merge");
  c.plane_merge_factor = p.real("plane_merge");
  c.reuse_factor = p.real("reuse");
  c.node_snap_factor = p.real("node_snap");
  c.correction_factor = p.real("correction");
  c.correction_points = static_cast<int>(p.integer("correction_points"));
  c.weight_grid = p.real("weight_grid");
  c.weight_endpoint = p.real("weight_endpoint");
  c.weight_curve = p.real("weight_curve");
  c.weight_node = p.real("weight_node");
  c.tangent_bonus = p.real("tangent_bonus");
  c.lambda = p.real("lambda");
  c.fidelity = p.string("fidelity") == "thesis" ? FidelityNorm::thesis : FidelityNorm::cassie_app;
  c.tangent_weight = p.real("tangent_weight");
  c.planarity_weight = p.real("planarity_weight");
  c.planarity = p.boolean("planarity");
  c.tangents = p.boolean("tangents");
  c.overlap_cut = p.boolean("overlap_cut");
  c.overlap_factor = p.real("overlap");
  c.closure_factor = p.real("closure");
  c.trim_dangling = p.boolean("trim_dangling");
  c.trim_fraction = p.real("trim_fraction");
  c.trim_factor = p.real("trim");
  c.max_solver_segments = static_cast<int>(p.integer("max_solver_segments"));
  c.line_axis_snap = p.boolean("line_axis_snap");
  c.line_keep_factor = p.real("line_keep");
  c.mirror_factor = p.real("mirror_snap");
  c.mirror_on_plane_factor = p.real("mirror_on_plane");
  c.surface_factor = p.real("surface_snap");
  c.on_surface = p.boolean("on_surface");
  const std::string& m = p.string("mirror");
  c.mirror = m == "off" ? MirrorMode::off : m == "plane" ? MirrorMode::plane : MirrorMode::workspace;
  c.preprocess = p.string("preprocess") == "cassie_app" ? cassie_app_preprocess() : PreprocessParams{};
  c.preprocess.delta = c.delta;
  c.preprocess.fit_error_factor = p.real("fit_error");
  c.preprocess.max_g1_angle = p.real("sharp_angle");
  c.preprocess.detect_lines = p.boolean("detect_lines");
  c.preprocess.remove_hooks = p.boolean("remove_hooks");
  c.preprocess.app_filter_input = p.boolean("filter_input");
  return c;
}

}  // namespace sketchlab::cassie
