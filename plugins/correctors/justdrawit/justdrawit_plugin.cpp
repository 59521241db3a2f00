// JustDrawIt (Grimm & Joshi 2012) stroke inference engine as a corrector
// plugin: 2D strokes (pixels + View) merged into 3D curves.
#include "jdi_params.hpp"
#include "justdrawit_corrector.hpp"
#include "sketchlab/plugin/plugin_api.hpp"

namespace {

using namespace sketchlab;

class JustDrawItCorrector : public Corrector {
 public:
  explicit JustDrawItCorrector(const Params& p) : params_(justdrawit::jdi_params_from(p)) {}
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    return justdrawit::justdrawit_correct(stroke, sketch, params_);
  }
  StrokeSpace stroke_space() const override { return StrokeSpace::pixels; }

 private:
  justdrawit::JdiParams params_;
};

PluginDescriptor describe() {
  return corrector_descriptor<JustDrawItCorrector>(
      "justdrawit", "1.0",
      "JustDrawIt (Grimm & Joshi 2012): 2D strokes merged into 3D curves by oversketch, extend, "
      "join, close and combine, with depth from the curves or a drawing surface",
      justdrawit::jdi_param_specs());
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
