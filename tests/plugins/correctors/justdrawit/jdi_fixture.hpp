#pragma once
// Helpers for the JustDrawIt tests: cameras, pixel strokes, and a Session
// folding strokes through the corrector (as `sketchlab run` does).
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>

#include "choice.hpp"
#include "jdi_params.hpp"
#include "justdrawit_corrector.hpp"
#include "point_list.hpp"
#include "network_curves.hpp"
#include "sketchlab/session.hpp"

namespace jdi_test {

using namespace sketchlab;
using namespace sketchlab::justdrawit;

inline View perspective_view(const Vec3& eye, const Vec3& target = Vec3::Zero(),
                             const Vec3& up = Vec3::UnitY()) {
  View v;
  v.view = look_at(eye, target, up);
  v.projection = perspective(std::numbers::pi / 4, 1.2, 0.1, 100.0);
  v.viewport = Vec4(0, 0, 1200, 1000);
  return v;
}

// Orthographic camera: 1 m spans 1000 px.
inline View ortho_view(const Vec3& eye, const Vec3& target = Vec3::Zero(),
                       const Vec3& up = Vec3::UnitY()) {
  View v;
  v.view = look_at(eye, target, up);
  const double hw = 0.6, hh = 0.5, n = 0.1, f = 100.0;
  Mat4 p = Mat4::Identity();
  p(0, 0) = 1 / hw;
  p(1, 1) = 1 / hh;
  p(2, 2) = -2 / (f - n);
  p(2, 3) = -(f + n) / (f - n);
  v.projection = p;
  v.viewport = Vec4(0, 0, 1200, 1000);
  return v;
}

inline Stroke pixel_stroke(StrokeId id, const View& v, const std::vector<Vec2>& px,
                           Layer layer = Layer::automatic) {
  Stroke s;
  s.id = id;
  s.view = v;
  s.samples_are_pixels = true;
  s.layer = layer;
  double t = 0.01 * static_cast<double>(id);
  for (const Vec2& p : px) {
    Sample smp;
    smp.position = Vec3(p.x(), p.y(), 0);
    smp.time = t += 0.005;
    s.samples.push_back(smp);
  }
  return s;
}

inline std::vector<Vec2> line_px(const Vec2& a, const Vec2& b, int n = 60) {
  std::vector<Vec2> out;
  for (int i = 0; i < n; ++i) out.push_back(a + (b - a) * (static_cast<double>(i) / (n - 1)));
  return out;
}

inline std::vector<Vec2> to_pixels(const View& v, const std::vector<Vec3>& pts) {
  std::vector<Vec2> out;
  for (const Vec3& p : pts) out.push_back(world_to_pixel(v, p).head<2>());
  return out;
}

class TestCorrector : public Corrector {
 public:
  explicit TestCorrector(JdiParams p) : p_(p) {}
  Correction correct(const Stroke& s, const Sketch& sk) override { return justdrawit_correct(s, sk, p_); }
  StrokeSpace stroke_space() const override { return StrokeSpace::pixels; }

 private:
  JdiParams p_;
};

struct Drawer {
  explicit Drawer(JdiParams p = {})
      : session(Workspace{}, std::make_shared<TestCorrector>(p), nullptr) {}
  StepReport draw(const View& v, const std::vector<Vec2>& px, Layer layer = Layer::automatic,
                  std::optional<Vec4> draw_plane = std::nullopt) {
    Stroke s = pixel_stroke(next++, v, px, layer);
    s.draw_plane = draw_plane;
    Event e;
    e.time = 0.1 * static_cast<double>(next);
    e.payload = StrokeEvent{s};
    return session.handle(e);
  }
  const Network& net() const { return session.sketch().network; }
  Points3 points(CurveId id) const { return curve_points(net().find_curve(id)->curve, 1e-3); }
  Points3 only_curve() const { return points(net().curves().begin()->first); }
  Session session;
  StrokeId next = 1;
};

// The corrector's decision for the stroke (CorrectionStats::outcomes).
inline std::optional<Decision> decision(const StepReport& r) {
  const auto it = r.stats.outcomes.find("decision");
  return it == r.stats.outcomes.end() ? std::nullopt : decision_from_string(it->second);
}

}  // namespace jdi_test
