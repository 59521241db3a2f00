// Plugin entry: the CASSIE corrector (see README.md).
#include "cassie_corrector.hpp"
#include "cassie_params.hpp"
#include "constraint_oracle.hpp"
#include "sketchlab/plugin/plugin_api.hpp"

namespace {

using namespace sketchlab;

class CassieCorrector : public Corrector {
 public:
  explicit CassieCorrector(const Params& p) : params_(cassie::params_from(p)) {
    if (const std::string& file = p.string("oracle"); !file.empty()) oracle_ = cassie::read_constraint_oracle(file);
  }
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    const auto it = oracle_.find(stroke.id);
    return cassie::correct_stroke(stroke, sketch, params_, it == oracle_.end() ? nullptr : &it->second);
  }

 private:
  cassie::CassieParams params_;
  cassie::ConstraintOracle oracle_;
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
