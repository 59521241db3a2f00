#include "soapfilm_params.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

#include "sketchlab/plugin/param_table.hpp"

namespace sketchlab::soapfilm {

namespace {

const ParamTable<SoapfilmParams>& parameters() {
  using P = SoapfilmParams;
  auto frame = [](auto field) {
    return [field](P& s) -> auto& { return s.search.frame.*field; };
  };
  static const auto table =
      ParamTable<P>()
          .real("sharp_angle", frame(&NodeFrameParams::sharp_angle), 0.0, std::numbers::pi / 2, "rad",
                   "θ: a node is sharp if a fitted direction leaves its plane by more than θ (CHI'21 §5.1; CASSIE app: "
                   "|n·t| > 0.5, π/6)")
          .real("sharp_error", frame(&NodeFrameParams::sharp_error), 0.0, 1.0, "",
                   "plane-fit error (RMS) above which a node is also sharp (thesis §3.3.2.2: 0.3; 1 = never, as the app)")
          .real("collinear_tangents", frame(&NodeFrameParams::collinear), 0.0, 1.0, "",
                   "largest |t_i x t_j| below which a node's normal is fitted to the directions towards the opposite nodes "
                   "(CASSIE app: 0.1)")
          .real("trim_angle", nested_field(&P::search, &CycleSearchParams::trim_angle), 0.0, std::numbers::pi / 2, "rad",
                   "transported vs node normal angle above which the turn is chosen in the transported normal's plane "
                   "(CASSIE app: π/3; π/2 = off)")
          .boolean("transport_through_two", nested_field(&P::search, &CycleSearchParams::transport_through_two),
                   "carry the transported normal across nodes with two segments instead of their fitted normal "
                   "(not in the CASSIE app)")
          .real("sharp_projection", nested_field(&P::search, &CycleSearchParams::sharp_projection), 0.0, 1.0, "",
                   "at a sharp node, candidates keep at least this much of their unit tangent on the transported plane "
                   "(CASSIE app: 0.7)")
          .real("tie_cos", nested_field(&P::search, &CycleSearchParams::tie_cos), -1.0, 1.0, "",
                   "segments leaving a node closer than this (cosine) are ordered by their opposite nodes (CASSIE app: 0.99)")
          .integer("transport_steps", nested_field(&P::search, &CycleSearchParams::transport_steps), 1.0, 1000.0, "",
                   "parallel-transport steps per cubic piece (CASSIE app: 20)")
          .integer("break_reach", nested_field(&P::search, &CycleSearchParams::break_reach), 0.0, 1000.0, "",
                   "a new segment entering a patch breaks it if it reaches the cycle again through at most this many "
                   "two-segment nodes (CASSIE app: 5)")
          .boolean("break_by_order", nested_field(&P::search, &CycleSearchParams::break_by_order),
                   "a new segment enters a patch when it sits between two consecutive cycle segments in the node's "
                   "order around its normal oriented by the cycle (CASSIE app, item 25); off: when it leaves into "
                   "the patch's mesh")
          .choice("close_rule", nested_field(&P::search, &CycleSearchParams::close_rule),
                  {{"into_start", CloseRule::into_start},
                   {"into_start_segment", CloseRule::into_start_segment},
                   {"at_start_node", CloseRule::at_start_node}},
                  "a walk closes when its turn takes the start segment again, or when it arrives back at the start "
                  "node (CASSIE app, item 24, read two ways)")
          .boolean("sharp_node_order", nested_field(&P::search, &CycleSearchParams::sharp_node_order),
                   "at a sharp node, order the candidates around the node's own normal oriented by the flip test "
                   "(item 23's order) instead of around the transported normal (CASSIE app, item 24)")
          .choice("broken_seeds", nested_field(&P::search, &CycleSearchParams::broken_seeds),
                  {{"one", BrokenSeeds::one}, {"all", BrokenSeeds::all}, {"at_break", BrokenSeeds::at_break}},
                  "segments of a broken patch searched first: one, all, or those at the node the breaking segment "
                  "leaves (CASSIE app, item 25)")
          .choice("hand_deleted", nested_field(&P::search, &CycleSearchParams::hand_deleted),
                  {{"forget", HandDeleted::forget},
                   {"not_remade", HandDeleted::not_remade},
                   {"counts", HandDeleted::counts}},
                  "a cycle whose patch the user deleted by hand, found again: made again (forget), not made "
                  "(not_remade), or not made and counted towards the two patches a segment may bound (counts; "
                  "CASSIE app, items 24-26)")
          .boolean("start_turn", nested_field(&P::search, &CycleSearchParams::start_turn),
                   "a segment's walks begin by turning at its start node with that node's normal instead of leaving "
                   "it along the segment (CASSIE app, item 25, read the other way)")
          .boolean("closed_seam_nodes", nested_field(&P::search, &CycleSearchParams::closed_seam_nodes),
                   "a closed curve's seam node stays a graph node when other curves split the curve (CASSIE app, "
                   "item 22)")
          .boolean("seed_split_segments", nested_field(&P::search, &CycleSearchParams::seed_split_segments),
                   "also search an old curve's segments split by a node the edit added on it (CASSIE app, item 25)")
          .boolean("manual_patches_count", nested_field(&P::search, &CycleSearchParams::manual_patches_count),
                   "manual patches count towards the two patches a segment may bound")
          .integer("max_cycle_segments", nested_field(&P::search, &CycleSearchParams::max_segments), 0.0, 1000.0, "",
                   "longest automatic cycle (segments); 0 = no limit (CASSIE app)")
          .boolean("reject_outer_boundary", nested_field(&P::search, &CycleSearchParams::reject_outer),
                   "reject cycles running clockwise around their normals (an open sheet's outer border; not in the app)")
          .integer("manual_max_segments", nested_field(&P::manual, &ManualPatchParams::max_segments), 1.0, 10000.0, "",
                   "longest manual cycle (segments)")
          .integer("manual_max_turns", nested_field(&P::manual, &ManualPatchParams::max_turns), 0.0, 10000.0, "",
                   "a manual walk gives up after this many turns where the tangents differ (cos < 0.8); 0 = no "
                   "limit (CASSIE app, item 26: 10)")
          .boolean("manual_manifold_first", nested_field(&P::manual, &ManualPatchParams::manifold_first),
                   "a manual walk takes segments bounding fewer than two patches before nearer others (CASSIE app, "
                   "item 26)")
          .real("edge_length", &P::edge_length, 1e-4, 1.0, "m",
                   "boundary sampling and target edge length of the patch meshes")
          .integer("max_boundary_points", &P::max_boundary_points, 3.0, 10000.0, "",
                   "boundary samples per patch at most (the spacing grows on long cycles)")
          .integer("remesh_iterations", nested_field(&P::mesh, &PatchMeshParams::remesh_iterations), 0.0, 100.0, "",
                   "isotropic remeshing iterations (CASSIE: 3)")
          .integer("smooth_iterations", nested_field(&P::mesh, &PatchMeshParams::smooth_iterations), 0.0, 1000.0, "",
                   "curvature-flow smoothing iterations (CASSIE: 10)")
          .real("smoothing_time", nested_field(&P::mesh, &PatchMeshParams::smoothing_time), 0.0, 10.0, "",
                   "curvature-flow time step relative to the squared boundary diameter");
  return table;
}

}  // namespace

std::vector<ParamSpec> soapfilm_param_specs() { return parameters().specs(); }

SoapfilmParams soapfilm_params(const Params& p) { return parameters().read(p); }

void parse_param_assignment(const std::string& assignment, std::map<std::string, ParamValue>& given) {
  const std::vector<ParamSpec> specs = soapfilm_param_specs();
  const auto eq = assignment.find('=');
  const std::string name = assignment.substr(0, eq);
  const auto spec = std::find_if(specs.begin(), specs.end(), [&](const ParamSpec& s) { return s.name == name; });
  if (eq == std::string::npos)
    throw std::invalid_argument("--param " + assignment +
                                ": expected NAME=VALUE with NAME a soapfilm parameter (sketchlab plugins soapfilm)");
  if (spec == specs.end()) {
    validate_params(specs, {{name, ParamValue{}}});  // the kernel's error for an unknown name, listing the declared ones
    throw std::logic_error("validate_params accepted an unknown parameter '" + name + "'");
  }
  given[spec->name] = parse_param_value(*spec, assignment.substr(eq + 1));
}

}  // namespace sketchlab::soapfilm
