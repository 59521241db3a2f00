// Plugin entry of the ScaffoldSketch corrector.
#include "scaffoldsketch_corrector.hpp"
#include "sketchlab/plugin/plugin_api.hpp"

namespace {

sketchlab::PluginDescriptor describe() {
  return sketchlab::corrector_descriptor<sketchlab::scaffoldsketch::ScaffoldSketchCorrector>(
      "scaffoldsketch", "1.0",
      "ScaffoldSketch (Yu et al. UIST 2021): IRLS scaffold lines and ticks, MVC shape curves "
      "through scaffold keypoints",
      sketchlab::scaffoldsketch::parameter_specs());
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
