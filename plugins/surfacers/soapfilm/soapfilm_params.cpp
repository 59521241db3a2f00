#include "soapfilm_params.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

namespace sketchlab::soapfilm {

std::vector<ParamSpec> soapfilm_param_specs() {
  const SoapfilmParams d;
  return {
      {"sharp_angle", ParamType::real, d.search.frame.sharp_angle, 0.0, std::numbers::pi / 2, {}, "rad",
       "θ: a node is sharp if a fitted direction leaves its plane by more than θ (CHI'21 §5.1; CASSIE app: "
       "|n·t| > 0.5, π/6)"},
      {"sharp_error", ParamType::real, d.search.frame.sharp_error, 0.0, 1.0, {}, "",
       "plane-fit error (RMS) above which a node is also sharp (thesis §3.3.2.2: 0.3; 1 = never, as the app)"},
      {"collinear_tangents", ParamType::real, d.search.frame.collinear, 0.0, 1.0, {}, "",
       "largest |t_i x t_j| below which a node's normal is fitted to the directions towards the opposite nodes "
       "(CASSIE app: 0.1)"},
      {"trim_angle", ParamType::real, d.search.trim_angle, 0.0, std::numbers::pi / 2, {}, "rad",
       "transported vs node normal angle above which the turn is chosen in the transported normal's plane "
       "(CASSIE app: π/3; π/2 = off)"},
      {"transport_through_two", ParamType::boolean, d.search.transport_through_two, {}, {}, {}, "",
       "carry the transported normal across nodes with two segments instead of their fitted normal "
       "(not in the CASSIE app)"},
      {"sharp_projection", ParamType::real, d.search.sharp_projection, 0.0, 1.0, {}, "",
       "at a sharp node, candidates keep at least this much of their unit tangent on the transported plane "
       "(CASSIE app: 0.7)"},
      {"tie_cos", ParamType::real, d.search.tie_cos, -1.0, 1.0, {}, "",
       "segments leaving a node closer than this (cosine) are ordered by their opposite nodes (CASSIE app: 0.99)"},
      {"transport_steps", ParamType::integer, std::int64_t{d.search.transport_steps}, 1.0, 1000.0, {}, "",
       "parallel-transport steps per cubic piece (CASSIE app: 20)"},
      {"break_reach", ParamType::integer, std::int64_t{d.search.break_reach}, 0.0, 1000.0, {}, "",
       "a new segment entering a patch breaks it if it reaches the cycle again through at most this many "
       "two-segment nodes (CASSIE app: 5)"},
      {"manual_patches_count", ParamType::boolean, d.search.manual_patches_count, {}, {}, {}, "",
       "manual patches count towards the two patches a segment may bound"},
      {"max_cycle_segments", ParamType::integer, std::int64_t{d.search.max_segments}, 0.0, 1000.0, {}, "",
       "longest automatic cycle (segments); 0 = no limit (CASSIE app)"},
      {"reject_outer_boundary", ParamType::boolean, d.search.reject_outer, {}, {}, {}, "",
       "reject cycles running clockwise around their normals (an open sheet's outer border; not in the app)"},
      {"manual_max_segments", ParamType::integer, std::int64_t{d.manual.max_segments}, 1.0, 10000.0, {}, "",
       "longest manual cycle (segments)"},
      {"edge_length", ParamType::real, d.edge_length, 1e-4, 1.0, {}, "m",
       "boundary sampling and target edge length of the patch meshes"},
      {"max_boundary_points", ParamType::integer, std::int64_t{d.max_boundary_points}, 3.0, 10000.0, {}, "",
       "boundary samples per patch at most (the spacing grows on long cycles)"},
      {"remesh_iterations", ParamType::integer, std::int64_t{d.mesh.remesh_iterations}, 0.0, 100.0, {}, "",
       "isotropic remeshing iterations (CASSIE: 3)"},
      {"smooth_iterations", ParamType::integer, std::int64_t{d.mesh.smooth_iterations}, 0.0, 1000.0, {}, "",
       "curvature-flow smoothing iterations (CASSIE: 10)"},
      {"smoothing_time", ParamType::real, d.mesh.smoothing_time, 0.0, 10.0, {}, "",
       "curvature-flow time step relative to the squared boundary diameter"},
  };
}

SoapfilmParams soapfilm_params(const Params& p) {
  SoapfilmParams s;
  s.search.frame.sharp_angle = p.real("sharp_angle");
  s.search.frame.sharp_error = p.real("sharp_error");
  s.search.frame.collinear = p.real("collinear_tangents");
  s.search.trim_angle = p.real("trim_angle");
  s.search.transport_through_two = p.boolean("transport_through_two");
  s.search.sharp_projection = p.real("sharp_projection");
  s.search.tie_cos = p.real("tie_cos");
  s.search.transport_steps = static_cast<int>(p.integer("transport_steps"));
  s.search.break_reach = static_cast<int>(p.integer("break_reach"));
  s.search.manual_patches_count = p.boolean("manual_patches_count");
  s.search.max_segments = static_cast<int>(p.integer("max_cycle_segments"));
  s.search.reject_outer = p.boolean("reject_outer_boundary");
  s.manual.max_segments = static_cast<int>(p.integer("manual_max_segments"));
  s.edge_length = p.real("edge_length");
  s.max_boundary_points = static_cast<int>(p.integer("max_boundary_points"));
  s.mesh.remesh_iterations = static_cast<int>(p.integer("remesh_iterations"));
  s.mesh.smooth_iterations = static_cast<int>(p.integer("smooth_iterations"));
  s.mesh.smoothing_time = p.real("smoothing_time");
  return s;
}

void parse_param_assignment(const std::string& assignment, std::map<std::string, ParamValue>& given) {
  const std::vector<ParamSpec> specs = soapfilm_param_specs();
  const auto eq = assignment.find('=');
  const std::string name = assignment.substr(0, eq);
  const auto spec = std::find_if(specs.begin(), specs.end(), [&](const ParamSpec& s) { return s.name == name; });
  if (eq == std::string::npos || spec == specs.end())
    throw std::invalid_argument("--param " + assignment +
                                ": expected NAME=VALUE with NAME a soapfilm parameter (sketchlab plugins soapfilm)");
  given[spec->name] = parse_param_value(*spec, assignment.substr(eq + 1));
}

}  // namespace sketchlab::soapfilm
