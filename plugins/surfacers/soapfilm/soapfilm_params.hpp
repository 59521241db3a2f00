#pragma once
// The plugin's parameters (defaults from CASSIE; see README.md).
#include <vector>

#include "cycle_search.hpp"
#include "manual_patch.hpp"
#include "patch_mesh.hpp"
#include "sketchlab/plugin/params.hpp"

namespace sketchlab::soapfilm {

struct SoapfilmParams {
  CycleSearchParams search;
  ManualPatchParams manual;
  PatchMeshParams mesh;
  double edge_length = 0.01;    // m, boundary sampling = target edge length
  // Boundary samples per patch at most: bounds one patch's mesh to ~250
  // vertices (~6 ms), the cost the 10 ms per patch target allows (README.md).
  int max_boundary_points = 48;
};

std::vector<ParamSpec> soapfilm_param_specs();
SoapfilmParams soapfilm_params(const Params& params);

}  // namespace sketchlab::soapfilm
