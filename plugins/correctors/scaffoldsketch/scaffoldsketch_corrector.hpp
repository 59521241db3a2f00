#pragma once
// The ScaffoldSketch corrector (Yu et al., UIST 2021): scaffold strokes
// become IRLS-corrected lines or ticks (§4.1), shape strokes become MVC curves
// through scaffold keypoints (§4.2).
#include <vector>

#include "scaffold_params.hpp"
#include "sketchlab/plugin/corrector.hpp"
#include "sketchlab/plugin/params.hpp"
#include "sketchlab/preprocess/preprocess.hpp"

namespace sketchlab::scaffoldsketch {

// The plugin's parameter specs, with the paper's defaults.
std::vector<ParamSpec> parameter_specs();

// Which algorithm a stroke gets: scaffold and guide strokes are scaffold
// lines; shape strokes are shape curves; automatic and free strokes are
// scaffold lines when the kernel's line detection (preprocess_stroke) finds
// a line, else shape curves.
enum class StrokeMode { scaffold, shape };

class ScaffoldSketchCorrector : public Corrector {
 public:
  explicit ScaffoldSketchCorrector(const Params& params);
  ScaffoldSketchCorrector(const ScaffoldParams& scaffold, const ShapeParams& shape,
                          const PreprocessParams& preprocess = {});
  Correction correct(const Stroke& stroke, const Sketch& sketch) override;

 private:
  ScaffoldParams scaffold_;
  ShapeParams shape_;
  PreprocessParams preprocess_;
};

}  // namespace sketchlab::scaffoldsketch
