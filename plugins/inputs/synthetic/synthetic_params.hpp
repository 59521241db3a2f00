#pragma once
// The plugin's parameter specs and their conversion to SynthesisParams.
#include <vector>

#include "session_synthesis.hpp"
#include "sketchlab/plugin/params.hpp"

namespace sketchlab::synthetic {

std::vector<ParamSpec> synthetic_param_specs();
// `params` validated against synthetic_param_specs().
SynthesisParams synthesis_params(const Params& params);

}  // namespace sketchlab::synthetic
