#pragma once
// Seeded random recordings covering every event type and awkward doubles
// (subnormals, -0, values with 17 significant digits).
#include <random>

#include "sketchlab/recording/recording.hpp"

namespace sketchlab::test {

inline double awkward(std::mt19937_64& rng, double scale) {
  std::uniform_int_distribution<int> pick(0, 9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  switch (pick(rng)) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return 5e-324;  // smallest subnormal
    case 3: return 0.1;
    case 4: return scale / 3.0;
    default: return scale * u(rng);
  }
}

inline Vec3 random_vec(std::mt19937_64& rng, double scale) {
  return {awkward(rng, scale), awkward(rng, scale), awkward(rng, scale)};
}

inline Workspace random_workspace(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> pos(0.01, 2.0);
  std::bernoulli_distribution coin;
  Workspace ws;
  ws.up = Vec3(0.1, 1.0, pos(rng));
  ws.grid_enabled = coin(rng);
  ws.grid_spacing = pos(rng);
  ws.grid_origin = random_vec(rng, 1.0);
  ws.mirror_enabled = coin(rng);
  ws.mirror_normal = Vec3(1.0, awkward(rng, 1.0), 0.0);
  ws.mirror_offset = awkward(rng, 0.5);
  ws.scale = pos(rng);
  return ws;
}

inline Curve random_curve(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> segs(1, 4);
  std::bernoulli_distribution coin;
  Curve c;
  const int k = segs(rng);
  c.kind = k == 1 && coin(rng) ? CurveKind::line : CurveKind::bezier;
  for (int i = 0; i < 3 * k + 1; ++i) c.control_points.push_back(random_vec(rng, 1.0));
  for (int i = 0; i <= k; ++i) c.sharp.push_back(coin(rng));
  if (coin(rng)) {
    c.control_points.back() = c.control_points.front();
    c.closed = true;
  }
  return c;
}

inline Stroke random_stroke(std::mt19937_64& rng, StrokeId id, double t0) {
  std::uniform_int_distribution<int> count(2, 30);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::bernoulli_distribution coin;
  std::bernoulli_distribution rare(0.2);
  Stroke s;
  s.id = id;
  s.layer = static_cast<Layer>(std::uniform_int_distribution<int>(0, 4)(rng));
  s.workspace_scale = 0.5 + 2.5 * unit(rng);
  const bool pixels = rare(rng);
  if (pixels || rare(rng)) {
    View v;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) v.view(r, c) = awkward(rng, 2.0);
    v.projection(0, 1) = 0.3;
    v.viewport = Vec4(0, 0, 1920, 1080.5);
    v.dpi = 120.0;
    s.view = v;
    s.samples_are_pixels = pixels;
  }
  const int n = count(rng);
  double t = t0;
  for (int i = 0; i < n; ++i) {
    Sample smp;
    smp.position = Vec3(0.01 * i, 0.0, 0.0) + random_vec(rng, pixels ? 1000.0 : 1.0);
    t += 0.011 * unit(rng);
    smp.time = t;
    smp.pressure = unit(rng);
    if (coin(rng)) smp.orientation = Quat(Vec4(unit(rng), -unit(rng), unit(rng), 0.5).normalized());
    s.samples.push_back(smp);
  }
  s.samples.back().position.x() += 0.5;  // never zero length
  return s;
}

inline Recording random_recording(std::uint64_t seed, int events) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> type(0, 10);
  Recording rec;
  rec.header.units = "m";
  rec.header.workspace = random_workspace(rng);
  rec.header.source = {{"generator", "random_recording"}, {"seed", std::to_string(seed)},
                       {"quote", "a \"quoted\" \\ value\twith ünïcode"}};
  double t = 0.0;
  for (int i = 0; i < events; ++i) {
    t += unit(rng) < 0.2 ? 0.0 : unit(rng);  // repeated times too
    Event e;
    e.time = t;
    switch (type(rng)) {
      case 0: e.payload = StrokeEvent{random_stroke(rng, static_cast<StrokeId>(i), t)}; break;
      case 1: e.payload = UndoEvent{}; break;
      case 2: e.payload = RedoEvent{}; break;
      case 3: e.payload = DeleteNearEvent{random_vec(rng, 1.0), 0.01 + unit(rng)}; break;
      case 4: e.payload = DeleteStrokeEvent{rng()}; break;
      case 5: e.payload = ModeEvent{static_cast<Layer>(std::uniform_int_distribution<int>(0, 4)(rng))}; break;
      case 6: e.payload = WorkspaceEvent{random_workspace(rng)}; break;
      case 7: e.payload = CorrectionEvent{unit(rng) < 0.5}; break;
      case 8: e.payload = AddPatchEvent{random_vec(rng, 1.0)}; break;
      case 9: e.payload = DeletePatchEvent{random_vec(rng, 1.0)}; break;
      default: e.payload = ReferenceEvent{static_cast<StrokeId>(i), "ground_truth", random_curve(rng)}; break;
    }
    rec.events.push_back(std::move(e));
  }
  return rec;
}

}  // namespace sketchlab::test
