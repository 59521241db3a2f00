// libFuzzer harness: pen strokes through the tablet stacks (configs/tablet.yaml):
// the analytic, justdrawit or freehand corrector (the first byte), loaded
// from this build's plugin directory as the app loads them. The bytes give
// the zoom, a camera (eye 0.3–4.3 m from a target near the origin, 20–100°
// field of view, 1600 x 1000 px), maybe a draw plane through the target, and
// up to 8 strokes of up to 64 samples at 120 Hz, each a walk of pen steps of
// at most 20 px from a start on the screen, with the odd glitch sample (from
// fuzz::Bytes::number, up to 1e5 px, NaN, infinite, 1e300) or repeated
// sample; a stroke may change the camera first (a second view, as
// JustDrawIt's oversketching needs), and once in a while a camera matrix
// entry is itself such a number (issue 17's C0: a singular camera). Then
// maybe a deletion near the target and an undo. Contract:
// fuzz_session.hpp's CheckedSession.
#include <array>
#include <cmath>
#include <numbers>

#include "fuzz_session.hpp"
#include "sketchlab/view.hpp"

using namespace sketchlab;
using fuzz::unit;
using fuzz::unit_vector;

namespace {

constexpr std::array<const char*, 3> correctors = {"analytic", "justdrawit", "freehand"};

Vec3 direction(fuzz::Bytes& b) {
  const Vec3 v = unit_vector(b);
  return v.norm() > 1e-3 ? v.normalized() : Vec3::UnitZ();
}

View camera(fuzz::Bytes& b, const Vec3& target) {
  View v;
  const Vec3 eye = target + (0.3 + b.byte() / 64.0) * direction(b);
  v.view = look_at(eye, target, Vec3::UnitY());
  v.projection = perspective((20.0 + 80.0 * b.byte() / 255.0) * std::numbers::pi / 180.0, 1.6, 0.01, 100.0);
  v.viewport = Vec4(0, 0, 1600, 1000);
  if (b.byte() == 255) v.view(b.byte() % 4, b.byte() % 4) = b.number(10.0);
  return v;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::silence_warnings();
  fuzz::Bytes b(data, size);
  const char* corrector = correctors[b.byte() % correctors.size()];
  Workspace ws;
  ws.scale = 0.5 + b.byte() / 64.0;
  fuzz::CheckedSession session(ws, fuzz::build_plugins().make_corrector(corrector, {}), nullptr);
  const Vec3 target = 0.2 * unit_vector(b);
  View view = camera(b, target);
  std::optional<Vec4> plane;
  if (b.flag()) {
    const Vec3 n = direction(b);
    plane = Vec4(n.x(), n.y(), n.z(), n.dot(target));
  }
  const int strokes = 1 + b.byte() % 8;
  for (int k = 0; k < strokes && !b.empty(); ++k) {
    if (k > 0 && b.byte() >= 224) view = camera(b, target);
    Stroke s;
    s.id = static_cast<StrokeId>(k + 1);
    s.layer = Layer::automatic;
    s.view = view;
    s.samples_are_pixels = true;
    s.draw_plane = plane;
    s.workspace_scale = ws.scale;
    const int n = 1 + b.byte() % 64;
    Vec2 p(800.0 + 800.0 * unit(b), 500.0 + 500.0 * unit(b));
    for (int i = 0; i < n; ++i) {
      Sample smp;
      const std::uint8_t kind = b.byte();
      if (kind == 255) {
        smp.position = Vec3(b.number(1e5), b.number(1e5), 0.0);
      } else {
        if (kind != 254 || i == 0) p += 20.0 * Vec2(unit(b), unit(b));
        smp.position = Vec3(p.x(), p.y(), 0.0);
      }
      smp.time = session.last_time() + i / 120.0;
      smp.pressure = b.byte() / 255.0;
      s.samples.push_back(smp);
    }
    session.handle(Event{0.0, StrokeEvent{std::move(s)}});
  }
  if (b.flag()) session.handle(Event{0.0, DeleteNearEvent{target + 0.1 * unit_vector(b), 0.05}});
  if (b.flag()) session.handle(Event{0.0, UndoEvent{}});
  return 0;
}
