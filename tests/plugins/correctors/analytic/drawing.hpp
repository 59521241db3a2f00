#pragma once
// A tablet drawing session through the analytic corrector, for the tests.
#include <memory>
#include <vector>

#include "analytic_corrector.hpp"
#include "demo_scenes.hpp"
#include "sketchlab/session.hpp"

namespace sketchlab::analytic::test {

struct Drawing {
  explicit Drawing(const View& v, AnalyticParams p = {})
      : view(v), session(Workspace{}, std::make_shared<AnalyticCorrector>(p), nullptr) {}

  // Draws the projection of a 3D path (pixel noise `noise`), returns the report.
  StepReport draw(const std::vector<Vec3>& path, double noise = 0.5) {
    const Stroke s = demo::projected_stroke(next++, view, path, noise, 17);
    return session.handle(Event{0.0, StrokeEvent{s}});
  }
  StepReport guideline(const Vec3& origin, const Vec3& dir, double noise = 0.5) {
    return draw(demo::guideline_path(view, origin, dir), noise);
  }
  const Sketch& sketch() const { return session.sketch(); }
  // The curves the last stroke added.
  std::vector<NetworkCurve> added_by(StrokeId id) const {
    std::vector<NetworkCurve> out;
    for (const auto& [cid, c] : sketch().network.curves())
      if (c.source_stroke == id) out.push_back(c);
    return out;
  }
  View view;
  Session session;
  StrokeId next = 1;
};

inline double stat(const StepReport& r, const char* key) {
  const auto it = r.stats.extra.find(key);
  return it == r.stats.extra.end() ? 0.0 : it->second;
}

}  // namespace sketchlab::analytic::test
