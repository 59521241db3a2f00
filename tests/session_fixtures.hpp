#pragma once
// Correctors and strokes for tests that drive a Session directly (kernel
// sessions, live sessions, the VR viewer's correction worker), so they need
// no plugin loading.
#include "sketchlab/session.hpp"

namespace sketchlab::test {

// The freehand baseline as a plain corrector. It counts its calls so tests
// can tell whether a session asked it (refused and undone events must not).
class FitCorrector : public Corrector {
 public:
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    ++calls;
    Correction c;
    c.edit = freehand_edit(stroke, sketch, {});
    return c;
  }
  int calls = 0;
};

// A stroke of `n` samples: sample i lies at position_at(i), at time
// t0 + dt * i. Callers pass the shape (line, arc, noisy curve) as the lambda;
// it must return a Vec3, not an Eigen expression (which would dangle).
template <class PositionAt>
Stroke sampled_stroke(StrokeId id, int n, double t0, double dt, PositionAt&& position_at) {
  Stroke s;
  s.id = id;
  for (int i = 0; i < n; ++i) {
    Sample sample;
    sample.position = position_at(i);
    sample.time = t0 + dt * i;
    s.samples.push_back(sample);
  }
  return s;
}

}  // namespace sketchlab::test
