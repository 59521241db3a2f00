// Plugin entry of the analytic-drawing corrector.
#include "analytic_corrector.hpp"
#include "sketchlab/plugin/plugin_api.hpp"

namespace {

sketchlab::PluginDescriptor describe() {
  return sketchlab::corrector_descriptor<sketchlab::analytic::AnalyticCorrector>(
      "analytic", "1.0",
      "Analytic drawing (Schmidt et al. 2009): 2D strokes become guidelines, ticks, or 3D lines "
      "and curves inferred from the scaffold by fitness F = S·G·ΣC",
      sketchlab::analytic::parameter_specs());
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
