// Plugin entry: the CASSIE corrector (see README.md).
#include "cassie_corrector.hpp"
#include "cassie_params.hpp"
#include "sketchlab/plugin/plugin_api.hpp"

namespace {

using namespace sketchlab;

class CassieCorrector : public Corrector {
 public:
  explicit CassieCorrector(const Params& p) : params_(cassie::params_from(p)) {}
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    return cassie::correct_stroke(stroke, sketch, params_);
  }

 private:
  cassie::CassieParams params_;
};

PluginDescriptor describe() {
  return corrector_descriptor<CassieCorrector>(
      "cassie", "1.0",
      "CASSIE stroke structuring (Yu et al. CHI 2021 §4): intersections selected greedily, "
      "planarity and tangent soft constraints, KKT solve",
      cassie::param_specs());
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
