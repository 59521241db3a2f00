#pragma once
// Per-event statistics as CSV: one row per handled event (strokes, commands).
#include <string>
#include <vector>

#include "sketchlab/session.hpp"

namespace sketchlab {

// Columns: index, time_s, event, stroke, latency_ms, corrected, iterations,
// subsets_tried, constraints_considered, constraints_enforced, then
// considered/enforced counts per constraint kind that occurs, curves_added,
// curves_removed, curves_replaced, patches_added, patches_removed, error.
// With timings=false the latency column is written as 0 (for byte-identical
// comparisons).
std::string steps_to_csv(const std::vector<StepReport>& steps, bool timings = true);

}  // namespace sketchlab
