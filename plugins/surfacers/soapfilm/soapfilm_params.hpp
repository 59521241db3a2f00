#pragma once
// The plugin's parameters (defaults from CASSIE; see README.md).
#include <map>
#include <string>
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
  // m, boundary sampling = target edge length (CASSIE app, item 27: 0.02 m).
  double edge_length = 0.02;
  // Boundary samples per patch at most: bounds one patch's mesh to ~120
  // vertices, for the per-patch meshing CPU p95 <= 5 ms target (on
  // vintage_car end to end: 4.7-5.0 ms at 40, 3.4 ms at 36; README.md,
  // Benchmarks); cycles longer than 36 x 2 cm get a coarser spacing.
  int max_boundary_points = 36;
};

std::vector<ParamSpec> soapfilm_param_specs();
SoapfilmParams soapfilm_params(const Params& params);
// Reads one "NAME=VALUE" command-line assignment of a soapfilm parameter (the
// tools' --param) into `given`. Throws std::invalid_argument naming the
// argument when it has no '=', ParamError listing the declared names when
// NAME is not a parameter, and ParamError for a bad value.
void parse_param_assignment(const std::string& assignment, std::map<std::string, ParamValue>& given);

}  // namespace sketchlab::soapfilm
