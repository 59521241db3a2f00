// The papers' no-auto-correct baseline: CASSIE's "Freehand" system (CHI 2021
// §6; the original app fits each stroke and nothing else) and
// ScaffoldSketch's "no auto-correct" condition. Each stroke is preprocessed
// (by default as the CASSIE app does in its Freehand system: input
// filtering, the line test, corners and Schneider fit, and no hook removal:
// its curves end exactly at the raw samples' ends) and added as one curve,
// with no constraints. See README.md.
#include <numbers>

#include "sketchlab/plugin/plugin_api.hpp"
#include "sketchlab/session.hpp"

namespace {

using namespace sketchlab;

// CASSIE's Freehand system: the app's preprocessing without hook removal.
PreprocessParams freehand_system() {
  PreprocessParams p = cassie_app_preprocess();
  p.remove_hooks = false;
  return p;
}

class FreehandCorrector : public Corrector {
 public:
  explicit FreehandCorrector(const Params& p) {
    params_ = p.string("rules") == "cassie_app" ? freehand_system() : PreprocessParams{};
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
  const PreprocessParams d = freehand_system();
  std::vector<ParamSpec> specs{
      {"rules", ParamType::choice, std::string("cassie_app"), {}, {}, {"cassie_app", "sketchlab"}, "",
       "cassie_app: the CASSIE app's preprocessing (input filtering, line test, corners and fit; "
       "reference items 1-4); sketchlab: the thesis §3.2.2 reading (kernel preprocess.hpp)"},
      {"delta", ParamType::real, d.delta, 0.001, 0.5, {}, "m",
       "small distance δ at zoom 1 (CASSIE default 0.02); thresholds are δ/s"},
      {"fit_error", ParamType::real, d.fit_error_factor, 0.01, 5.0, {}, "δ",
       "poly-Bézier fitting tolerance as a multiple of δ (CASSIE: 0.5)"},
      {"sharp_angle", ParamType::real, d.max_g1_angle, 0.05, std::numbers::pi / 2, {}, "rad",
       "direction turn above which a sample is a corner (π/4)"},
      {"detect_lines", ParamType::boolean, d.detect_lines, {}, {}, {}, "",
       "fit straight strokes with a line"},
      {"remove_hooks", ParamType::boolean, d.remove_hooks, {}, {}, {}, "",
       "cut hooks at both ends of the stroke (off: CASSIE's Freehand system keeps the raw ends)"},
  };
  return corrector_descriptor<FreehandCorrector>(
      "freehand", "1.1", "no auto-correct baseline (CASSIE's Freehand system): preprocessing and curve fitting only",
      std::move(specs));
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
