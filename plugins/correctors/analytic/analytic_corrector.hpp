#pragma once
// The analytic-drawing corrector (Schmidt et al. 2009): 2D strokes become
// guidelines, ticks, inferred 3D lines and curves, or stay free; free strokes
// near new geometry are re-inferred (§2.1).
#include "analytic_params.hpp"
#include "sketchlab/plugin/corrector.hpp"

namespace sketchlab::analytic {

class AnalyticCorrector : public Corrector {
 public:
  explicit AnalyticCorrector(const Params& p) : params_(params_from(p)) {}
  explicit AnalyticCorrector(const AnalyticParams& p) : params_(p) {}
  Correction correct(const Stroke& stroke, const Sketch& sketch) override;
  // Schmidt et al. infer depth from the 2D strokes themselves (§2.1).
  StrokeSpace stroke_space() const override { return StrokeSpace::pixels; }

 private:
  AnalyticParams params_;
};

// 2D strokes whose correction added nothing (free strokes), by id.
std::vector<StrokeId> free_strokes(const Sketch& sketch);

}  // namespace sketchlab::analytic
