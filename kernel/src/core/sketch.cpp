#include "sketchlab/sketch.hpp"

#include <set>

namespace sketchlab {

std::vector<CurveId> curves_of_stroke(const Sketch& sketch, StrokeId stroke) {
  std::vector<CurveId> out;
  for (const auto& [id, curve] : sketch.network.curves())
    if (curve.source_stroke == stroke) out.push_back(id);
  return out;
}

std::vector<StrokeId> live_strokes(const Sketch& sketch) {
  std::vector<StrokeId> out;
  std::set<StrokeId> seen;
  for (const HistoryEntry& entry : sketch.history.done)
    if (entry.stroke && seen.insert(*entry.stroke).second) out.push_back(*entry.stroke);
  return out;
}

std::vector<StrokeId> strokes_with_curves(const Sketch& sketch) {
  std::set<StrokeId> drawn;
  for (const auto& [id, c] : sketch.network.curves()) drawn.insert(c.source_stroke);
  std::vector<StrokeId> out;
  for (StrokeId s : live_strokes(sketch))
    if (drawn.count(s)) out.push_back(s);
  return out;
}

}  // namespace sketchlab
