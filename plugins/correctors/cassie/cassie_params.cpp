#include "cassie_params.hpp"

#include "sketchlab/plugin/param_table.hpp"
#include "sketchlab/workspace.hpp"

namespace sketchlab::cassie {

PreprocessParams cassie_structuring_preprocess() {
  PreprocessParams p = cassie_app_preprocess();
  p.app_trim_last_end = true;
  return p;
}

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
  t.dangling_snap = p.dangling_snap_factor * t.delta;
  t.correction = p.correction_factor * t.delta;
  t.overlap = p.overlap_factor * t.delta;
  t.closure = p.closure_factor * t.delta;
  t.trim = p.trim_factor * t.delta;
  t.line_keep = p.line_keep_factor * t.delta;
  t.mirror = p.mirror_factor * t.delta;
  t.on_plane = p.mirror_on_plane_factor * t.delta;
  t.surface = p.surface_factor * t.delta;
  t.oracle = p.oracle_radius_factor * t.delta;
  return t;
}

namespace {

// `preprocess` picks the preprocessing the other preprocessing parameters
// are read onto.
struct Settings {
  CassieParams params;
  std::string preprocess_rules = "cassie_app";
  std::string oracle;  // read by the plugin (params.string("oracle"))
};

const ParamTable<Settings>& parameters() {
  using C = CassieParams;
  const double pi = std::numbers::pi;
  auto c = [](auto field) { return nested_field(&Settings::params, field); };
  auto pre = [](auto field) {
    return [field](Settings& s) -> auto& { return s.params.preprocess.*field; };
  };
  static const auto table =
      ParamTable<Settings>()
          .real("delta", c(&C::delta), 0.001, 0.5, "m",
                "small distance δ at zoom 1 (thesis §3.2.3.1: 0.02); thresholds are δ/s")
          .real("angle", c(&C::angle), 0.01, pi / 2, "rad",
                "angular threshold θ for tangents, overlaps, axis planes and axis lines (π/6)")
          .real("brush", c(&C::brush_factor), 0.1, 10.0, "δ",
                "radius of the brush sphere that detects curves and the mirror plane while drawing "
                "(item 6 gives 2δ, the sphere's diameter: the app's logs cut off at δ + 1.5 mm)")
          .real("proximity", c(&C::proximity_factor), 0.1, 10.0, "δ",
                "r_detect (thesis §3.2.3.2: 2δ): grid points (item 19), line end snaps (item 17), planarity "
                "(item 14)")
          .real("collider_radius", c(&C::collider_radius), 0.0, 0.1, "m",
                "radius of the collider tube around each curve (item 6: 1.5 mm, not scaled)")
          .real("brush_step", c(&C::brush_step), 0.001, 1.0, "s",
                "time step at which the brush is tested (item 6: the 0.02 s physics step)")
          .real("merge", c(&C::merge_factor), 0.0, 5.0, "δ",
                "a constraint this close to the previous one replaces or is dropped for it (item 7: δ/2)")
          .real("plane_merge", c(&C::plane_merge_factor), 0.0, 5.0, "δ",
                "two consecutive mirror-plane constraints this close are one (item 7: δ)")
          .real("reuse", c(&C::reuse_factor), 0.0, 5.0, "δ",
                "a constraint within this of an anchor of its Bézier reuses it, else splits (item 12: δ)")
          .real("node_snap", c(&C::node_snap_factor), 0.0, 5.0, "δ",
                "a target snaps to an end node (two incidences or more) of the crossed piece within this "
                "(item 8: δ)")
          .real("dangling_snap", c(&C::dangling_snap_factor), 0.0, 5.0, "δ",
                "a target this close to the crossed curve's own end node with one incidence joins that node "
                "(item 22: a node within δ on the old curve is reused; 0: item 8's snap alone)")
          .real("correction", c(&C::correction_factor), 0.0, 5.0, "δ",
                "targets tried on the old curve around the detected one, ± this (item 8: δ/2)")
          .integer("correction_points", c(&C::correction_points), 0.0, 64.0, "",
                   "how many targets are tried on the old curve (item 8: 6; 0 keeps the detected target)")
          .boolean("corrected_node_snap", c(&C::corrected_node_snap),
                   "item 8's node snap (node_snap, dangling_snap) is tried again at the target the correction "
                   "moved, as the app's GetConstraint makes the corrected constraint (off: at detection only)")
          .boolean("correction_keeps_target", c(&C::correction_keeps_target),
                   "the detected target is tried too, kept when nearest the new curve (a second reading of item "
                   "8; off: the 6 points only)")
          .real("weight_grid", c(&C::weight_grid), 0.0, 100.0, "",
                "connectivity weight of a grid point or the mirror plane (CHI eq. 3: 1)")
          .real("weight_endpoint", c(&C::weight_endpoint), 0.0, 100.0, "",
                "weight at least this for a constraint within δ of a stroke end (item 11: 1.25)")
          .real("weight_curve", c(&C::weight_curve), 0.0, 100.0, "",
                "connectivity weight of another curve (CHI eq. 3: 1.5)")
          .real("weight_node", c(&C::weight_node), 0.0, 100.0, "",
                "connectivity weight of an existing intersection (CHI eq. 3: 2)")
          .real("tangent_bonus", c(&C::tangent_bonus), 0.0, 100.0, "",
                "added to the weight of a constraint whose tangents align (item 11: 0.5)")
          .choice("node_alignment", c(&C::node_alignment),
                  std::vector<std::pair<std::string, NodeAlignment>>{{"opposite", NodeAlignment::opposite},
                                                                     {"same", NodeAlignment::same}},
                  "at an existing node the tangents align when the two curves' parametric tangents point "
                "opposite ways (item 11 as CASSIE's logs show it) or the same way")
          .real("lambda", c(&C::lambda), 0.0, 1.0, "",
                "fidelity weight λ in E = λ·E_fidelity + (1−λ)·E_connectivity (CHI §4.3: 0.6)")
          .choice("fidelity", c(&C::fidelity),
                  std::vector<std::pair<std::string, FidelityNorm>>{{"cassie_app", FidelityNorm::cassie_app},
                                                                    {"thesis", FidelityNorm::thesis}},
                  "E_fidelity normalisation: cassie_app (item 13: positions over (2δ)², halves) or thesis "
                "(eq. 3.2: positions over the stroke span L²)")
          .real("position_scale", c(&C::position_scale), 0.01, 1000.0, "δ",
                "fidelity=cassie_app divides E_fidelity's position term by (this·δ)² (item 13: 2); larger "
                "lets a constrained curve move more as a whole")
          .choice("connectivity", c(&C::connectivity),
                  std::vector<std::pair<std::string, ConnectivityTotal>>{{"cassie_app", ConnectivityTotal::cassie_app},
                                                                         {"thesis", ConnectivityTotal::thesis}},
                  "E_connectivity's total weight: cassie_app (item 13: constraints that got an anchor) or thesis "
                "(eq. 3.12: every detected constraint)")
          .real("tangent_weight", c(&C::tangent_weight), 0.0, 1e6, "",
                "E_tangent = w/|e₀|²·|T×e|² on the edge at an aligned constraint (item 14: 2)")
          .real("planarity_weight", c(&C::planarity_weight), 0.0, 1e6, "",
                "E_planar multiplier, (1/(N−1))·Σ(n·e)²/|e₀|² (item 14: 1)")
          .boolean("planarity", c(&C::planarity),
                   "planarity soft constraint (item 14)")
          .choice("planarity_test", c(&C::planarity_test),
                  std::vector<std::pair<std::string, PlanarityTest>>{{"fitted", PlanarityTest::fitted},
                                                                     {"snapped", PlanarityTest::snapped}},
                  "item 14's 2δ test measures the control points against the least-squares plane, snapped to "
                "an axis afterwards (fitted: CHI §4.2, as CASSIE's planar flags show) or against the snapped "
                "plane (snapped)")
          .boolean("tangents", c(&C::tangents),
                   "tangent alignment soft constraints at intersections (item 14)")
          .boolean("overlap_cut", c(&C::overlap_cut),
                   "cut a stroke end that runs along the curve it meets (item 9)")
          .real("overlap", c(&C::overlap_factor), 0.0, 10.0, "δ",
                "an end constraint this close to the stroke end may cut the overlap (item 9: 2δ)")
          .real("closure", c(&C::closure_factor), 0.0, 10.0, "δ",
                "a poly-Bézier whose ends are this close is closed, a hard constraint (item 10: 2δ)")
          .boolean("trim_dangling", c(&C::trim_dangling),
                   "cut the short piece beyond the first/last enforced intersection (item 16)")
          .real("trim_fraction", c(&C::trim_fraction), 0.0, 1.0, "",
                "dangling pieces under this fraction of the length ... (item 16: 0.15)")
          .real("trim", c(&C::trim_factor), 0.0, 20.0, "δ",
                "... and under this length are cut (item 16: 3δ)")
          .integer("max_solver_segments", c(&C::max_solver_segments), 0.0, 1e6, "",
                   "poly-Béziers with more segments are returned unconstrained (item 5: 10; 0: no limit)")
          .boolean("line_axis_snap", c(&C::line_axis_snap),
                   "align lines within θ of an axis to it (item 17)")
          .real("line_keep", c(&C::line_keep_factor), 0.0, 5.0, "δ",
                "of two line constraints this close one is kept; a node needs the line this close "
                "(item 17: 0.2δ)")
          .real("mirror_snap", c(&C::mirror_factor), 0.0, 10.0, "δ",
                "project the whole stroke onto the mirror plane within this (item 18: 1.25δ)")
          .real("mirror_on_plane", c(&C::mirror_on_plane_factor), 0.0, 10.0, "δ",
                "an intersection this close to the mirror plane is on it (item 18: 0.1δ)")
          .real("surface_snap", c(&C::surface_factor), 0.0, 10.0, "δ",
                "project control points this close onto a patch (item 20: 2.5δ; thesis text 2δ)")
          .boolean("on_surface", c(&C::on_surface),
                   "project strokes drawn on a patch onto it (item 20)")
          .choice("surface_touch", c(&C::surface_touch),
                  std::vector<std::pair<std::string, SurfaceTouch>>{{"brush", SurfaceTouch::brush},
                                                                    {"control_points", SurfaceTouch::control_points}},
                  "brush: the patch is touched when a raw hand position is within the brush radius of its mesh "
                  "away from every curve's collider (items 6, 20); control_points: when a control point is "
                  "within surface_snap")
          .choice("surface_span", c(&C::surface_span),
                  std::vector<std::pair<std::string, SurfaceSpan>>{{"box", SurfaceSpan::box},
                                                                   {"stroke_ends", SurfaceSpan::stroke_ends},
                                                                   {"brush", SurfaceSpan::brush}},
                  "when the patch spans the stroke, which is then projected whole (item 20). box: the mesh's "
                  "box grown by surface_snap holds every control point; stroke_ends: also the stroke's first and "
                  "last hand positions are within the brush radius of the mesh; brush: also every hand position "
                  "away from the curves is")
          .choice("mirror", c(&C::mirror),
                  std::vector<std::pair<std::string, MirrorMode>>{
                      {"workspace", MirrorMode::workspace}, {"plane", MirrorMode::plane}, {"off", MirrorMode::off}},
                  "workspace: snap to the mirror plane and add the mirrored copy (paper); plane: snap only "
                "(replaying imported CASSIE sessions, which record both twins); off: ignore the mirror")
          .choice("preprocess", &Settings::preprocess_rules, std::vector<std::string>{"cassie_app", "sketchlab"},
                  "cassie_app: the app's input filtering, line test, hooks, corners and fit (items 1-4); "
                "sketchlab: the thesis §3.2.2 reading (kernel preprocess.hpp)")
          .boolean("filter_input", pre(&PreprocessParams::app_filter_input),
                   "drop samples closer than 0.1δ, strokes too short or brief, samples of the first and last "
                "0.02 s (item 1; cassie_app preprocessing)")
          .boolean("trim_last_end", pre(&PreprocessParams::app_trim_last_end),
                   "end the curve 0.02 s of hand motion before the last sample (the curves of CASSIE's "
                "structuring never reach it, README); false: item 1 as stated, both end samples kept")
          .real("input_spacing", c(&C::input_spacing_factor), 0.0, 5.0, "δ",
                "before preprocessing, insert points in gaps between samples longer than this (0: off); "
                "exported CASSIE sessions are RDP-thinned at 2 mm, the app's turn rules saw 90 Hz (items 3-4)")
          .real("fit_error", pre(&PreprocessParams::fit_error_factor), 0.01, 5.0, "δ",
                "poly-Bézier fitting tolerance (item 4: 0.5δ)")
          .real("sharp_angle", pre(&PreprocessParams::max_g1_angle), 0.05, pi, "rad",
                "direction turn above which a sample is a corner (item 4: π/4)")
          .boolean("detect_lines", pre(&PreprocessParams::detect_lines),
                   "fit straight strokes with a line (item 2)")
          .boolean("remove_hooks", pre(&PreprocessParams::remove_hooks),
                   "cut hooks at both ends of the stroke (item 3)")
          .choice("hook_turn", pre(&PreprocessParams::app_hook_turn),
                  std::vector<std::pair<std::string, TurnSpan>>{{"consecutive", TurnSpan::consecutive},
                                                                {"across", TurnSpan::across}},
                  "item 3's turn of the averaged direction: from one sample to the next, or across the "
                "sample (between its neighbours' directions; cassie_app preprocessing)")
          .string("oracle", &Settings::oracle,
                  "a file of the constraint targets a reference applied per stroke (constraint_oracle.hpp; "
                  "`sketchlab fidelity --cassie-subset` writes CASSIE's): a listed stroke enforces the constraint "
                  "nearest each applied target (within oracle_radius), no search; \"\" (default): the search "
                  "(item 15)")
          .real("oracle_radius", c(&C::oracle_radius_factor), 0.0, 5.0, "δ",
                "with oracle: the detected constraint nearest to an applied target, if within this, is enforced "
                "(δ/2: items 7 and 8 merge or move a target by up to that)")
          .boolean("oracle_positions", c(&C::oracle_positions),
                   "with oracle: a matched constraint is enforced at the position the reference logged, not at "
                   "ours (items 7-8 set ours): what still differs is the curve")
          .check([](Settings& s) { s.params.preprocess.delta = s.params.delta; });
  return table;
}

}  // namespace

std::vector<ParamSpec> param_specs() { return parameters().specs(); }

CassieParams params_from(const Params& p) {
  Settings s = parameters().read(p);
  if (s.preprocess_rules != "cassie_app") {
    Settings base;
    base.params.preprocess = PreprocessParams{};
    base.preprocess_rules = s.preprocess_rules;
    s = parameters().read(p, base);
  }
  return s.params;
}

}  // namespace sketchlab::cassie
