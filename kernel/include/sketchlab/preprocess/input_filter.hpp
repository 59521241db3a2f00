#pragma once
// Input filtering of the CASSIE app (reference item 1,
// `DrawController.UpdateStroke/CommitStroke`, `InputStroke.IsValid/
// GetSafePoints`): a sample is taken only when the hand has moved far enough
// since the last one; strokes too short (or too brief with close ends) are
// dropped; samples in the first and last moments are removed, the two end
// samples kept (the trigger press and release shake the hand).
#include <cstddef>
#include <string>
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab {

// Distances in the units of the points (the pipeline passes δ/s multiples),
// times in seconds.
struct InputFilterParams {
  double min_step = 0.002;      // a sample is taken when it is > this from the last taken (0.1δ)
  double min_length = 0.01;     // strokes shorter than this are dropped (0.5δ)
  double min_duration = 0.2;    // ... and those briefer than this with ends closer than min_length
  double end_trim = 0.02;       // samples this close in time to either end are removed
};

struct FilteredInput {
  std::vector<std::size_t> indices;  // kept input indices, increasing (first is 0)
  bool dropped = false;              // CASSIE would not keep the stroke
  std::string reason;                // why it was dropped
};

// points (n >= 1, finite) with times (same size, non-decreasing; or empty:
// then the duration rule and the end trim are skipped). Throws
// std::invalid_argument for mismatched sizes or negative parameters.
FilteredInput filter_input(const std::vector<Vec3>& points, const std::vector<double>& times,
                           const InputFilterParams& params);

}  // namespace sketchlab
