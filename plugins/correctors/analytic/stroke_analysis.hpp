#pragma once
// What one 2D stroke becomes against a scaffold: a guideline, a dimension
// tick, a 3D line (§3.1), a 3D curve (§3.2) or nothing (a free stroke, §2.1).
#include <map>
#include <string>
#include <vector>

#include "analytic_params.hpp"
#include "scaffold.hpp"
#include "sketchlab/constraint.hpp"
#include "sketchlab/sketch.hpp"

namespace sketchlab::analytic {

struct StrokeOutcome {
  enum class Kind { free, guideline, tick, line, curve } kind = Kind::free;
  std::vector<NetworkCurve> added;     // ids not yet assigned (0)
  std::vector<NetworkCurve> replaced;  // guidelines receiving ticks
  std::vector<Constraint> constraints;
  std::map<std::string, double> stats;
  std::string reason;  // why the stroke stayed free
};

// `aids`: guidelines and ticks are recognised (off when re-inferring a free
// stroke, which was not one when drawn). Throws std::invalid_argument when
// the stroke's view is unusable.
StrokeOutcome analyse_stroke(const Stroke& stroke, const Scaffold& scaffold, const Sketch& sketch,
                             const AnalyticParams& p, bool aids);

}  // namespace sketchlab::analytic
