#include "soapfilm_params.hpp"

#include <numbers>

namespace sketchlab::soapfilm {

std::vector<ParamSpec> soapfilm_param_specs() {
  const SoapfilmParams d;
  return {
      {"sharp_error", ParamType::real, d.search.frame.sharp_error, 0.0, 1.0, {}, "",
       "plane-fit error (RMS of unit tangents) above which a node is sharp (thesis §3.3.2.2: 0.3)"},
      {"sharp_angle", ParamType::real, d.search.frame.sharp_angle, 0.0, std::numbers::pi / 2, {}, "rad",
       "θ: a node is sharp if some tangent leaves the fitted plane by more than θ (CHI'21 §5.1, π/6)"},
      {"trim_angle", ParamType::real, d.search.trim_angle, 0.0, std::numbers::pi / 2, {}, "rad",
       "transported vs node normal angle above which a segment is treated as a trim curve"},
      {"max_cycle_segments", ParamType::integer, std::int64_t{d.search.max_segments}, 1.0, 1000.0, {}, "",
       "longest automatic cycle (segments)"},
      {"reject_outer_boundary", ParamType::boolean, d.search.reject_outer, {}, {}, {}, "",
       "reject cycles running clockwise around their normals (an open sheet's outer border)"},
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
  s.search.frame.sharp_error = p.real("sharp_error");
  s.search.frame.sharp_angle = p.real("sharp_angle");
  s.search.trim_angle = p.real("trim_angle");
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

}  // namespace sketchlab::soapfilm
