// The papers' no-auto-correct baseline: CASSIE's "Freehand" system (CHI 2021
// §6; the original app fits each stroke and nothing else) and
// ScaffoldSketch's "no auto-correct" condition. Each stroke is preprocessed
// (by default as the CASSIE app does in its Freehand system: input
// filtering, the line test, corners and Schneider fit, and no hook removal:
// its curves end exactly at the raw samples' ends) and added as one curve,
// with no constraints. See README.md.
#include <numbers>

#include "sketchlab/plugin/param_table.hpp"
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

// `rules` picks the preprocessing the other parameters are read onto.
struct FreehandSettings {
  std::string rules = "cassie_app";
  PreprocessParams preprocess = freehand_system();
};

const ParamTable<FreehandSettings>& parameters() {
  auto pre = [](auto field) { return nested_field(&FreehandSettings::preprocess, field); };
  static const auto table =
      ParamTable<FreehandSettings>()
          .choice("rules", &FreehandSettings::rules, std::vector<std::string>{"cassie_app", "sketchlab"},
                  "cassie_app: the CASSIE app's preprocessing (input filtering, line test, corners and fit; "
                  "reference items 1-4); sketchlab: the thesis §3.2.2 reading (kernel preprocess.hpp)")
          .real("delta", pre(&PreprocessParams::delta), 0.001, 0.5, "m",
                "small distance δ at zoom 1 (CASSIE default 0.02); thresholds are δ/s")
          .real("fit_error", pre(&PreprocessParams::fit_error_factor), 0.01, 5.0, "δ",
                "poly-Bézier fitting tolerance as a multiple of δ (CASSIE: 0.5)")
          .real("sharp_angle", pre(&PreprocessParams::max_g1_angle), 0.05,
                std::numbers::pi / 2, "rad", "direction turn above which a sample is a corner (π/4)")
          .boolean("detect_lines", pre(&PreprocessParams::detect_lines),
                   "fit straight strokes with a line")
          .boolean("remove_hooks", pre(&PreprocessParams::remove_hooks),
                   "cut hooks at both ends of the stroke (off: CASSIE's Freehand system keeps the raw ends)");
  return table;
}

class FreehandCorrector : public Corrector {
 public:
  explicit FreehandCorrector(const Params& p) {
    FreehandSettings s = parameters().read(p);
    // rules=sketchlab: the same fields read onto the kernel's own defaults.
    if (s.rules != "cassie_app") s = parameters().read(p, {s.rules, PreprocessParams{}});
    params_ = s.preprocess;
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
  return corrector_descriptor<FreehandCorrector>(
      "freehand", "1.1", "no auto-correct baseline (CASSIE's Freehand system): preprocessing and curve fitting only",
      parameters().specs());
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
