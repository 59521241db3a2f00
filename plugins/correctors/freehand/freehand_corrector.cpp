// The papers' no-auto-correct baseline (CASSIE's "Freehand" system,
// ScaffoldSketch's "no auto-correct" condition): each stroke is preprocessed
// (hook removal, line detection, G1 poly-Bézier fit) and added as one curve,
// with no constraints.
#include <numbers>

#include "sketchlab/plugin/plugin_api.hpp"
#include "sketchlab/session.hpp"

namespace {

using namespace sketchlab;

class FreehandCorrector : public Corrector {
 public:
  explicit FreehandCorrector(const Params& p) {
    if (p.string("rules") == "cassie_app") params_ = cassie_app_preprocess();
    params_.delta = p.real("delta");
    params_.fit_error_factor = p.real("fit_error");
    params_.max_g1_angle = p.real("sharp_angle");
    params_.detect_lines = p.boolean("detect_lines");
    params_.remove_hooks = p.boolean("remove_hooks");
  }
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    Correction c;
    c.edit = freehand_edit(stroke, sketch, params_);
    return c;
  }

 private:
  PreprocessParams params_;
};

PluginDescriptor describe() {
  const PreprocessParams d;
  std::vector<ParamSpec> specs{
      {"rules", ParamType::choice, std::string("cassie_app"), {}, {}, {"cassie_app", "sketchlab"}, "",
       "cassie_app: the CASSIE app's Freehand preprocessing (input filtering, line test, corners "
       "and Schneider fit as the app); sketchlab: the thesis §3.2.2 reading (preprocess.hpp)"},
      {"delta", ParamType::real, d.delta, 0.001, 0.5, {}, "m",
       "small distance δ at zoom 1 (CASSIE default 0.02); thresholds are δ/s"},
      {"fit_error", ParamType::real, d.fit_error_factor, 0.01, 5.0, {}, "δ",
       "poly-Bézier fitting tolerance as a multiple of δ (CASSIE: 0.5)"},
      {"sharp_angle", ParamType::real, d.max_g1_angle, 0.05, std::numbers::pi / 2, {}, "rad",
       "tangent turn above which a joint is sharp (π/4)"},
      {"detect_lines", ParamType::boolean, d.detect_lines, {}, {}, {}, "",
       "fit straight strokes with a line"},
      {"remove_hooks", ParamType::boolean, d.remove_hooks, {}, {}, {}, "",
       "cut hooks at both ends of the stroke"},
  };
  return corrector_descriptor<FreehandCorrector>(
      "freehand", "1.0", "no auto-correct baseline: preprocessing and curve fitting only",
      std::move(specs));
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
