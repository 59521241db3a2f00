// libFuzzer harness: hand strokes through a stack a VR user draws with,
// SKETCHLAB_FUZZ_CORRECTOR + SKETCHLAB_FUZZ_SURFACER (fuzz/CMakeLists.txt:
// cassie + soapfilm in fuzz_stroke_session, scaffoldsketch + hermite_rbf in
// fuzz_stroke_session_scaffold), loaded from this build's plugin directory
// as the app loads them (issues 15 and 16: real sessions, within a frame,
// without crashing). The bytes give the workspace (mirror,
// grid, zoom) and up to 8 strokes of up to 48 samples at 90 Hz, each a walk
// of hand steps of at most 2.5 cm from a start in a 1 m box, with the odd
// glitch sample (from fuzz::Bytes::number: NaN, infinite, 1e300, ...) or
// repeated sample; then maybe a deletion near a stroke, an undo and a manual
// patch. Contract: fuzz_session.hpp's CheckedSession.
#include "fuzz_session.hpp"

using namespace sketchlab;
using fuzz::unit_vector;

namespace {

// The surfacer's defaults, but the Hermite RBF's marching-cubes grid at 16
// cells instead of 64: its grid evaluation runs about 100 times slower under
// the fuzzer's coverage counters than in Release (an eight-stroke input: 17 s
// against 0.14 s), and the coarser grid takes the same code paths.
std::map<std::string, ParamValue> surfacer_params() {
  if (std::string_view(SKETCHLAB_FUZZ_SURFACER) == "hermite_rbf") return {{"resolution", std::int64_t{16}}};
  return {};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::silence_warnings();
  fuzz::Bytes b(data, size);
  Workspace ws;
  ws.mirror_enabled = b.flag();
  ws.grid_enabled = b.flag();
  ws.scale = 0.5 + b.byte() / 64.0;
  fuzz::CheckedSession session(ws, fuzz::build_plugins().make_corrector(SKETCHLAB_FUZZ_CORRECTOR, {}),
                               fuzz::build_plugins().make_surfacer(SKETCHLAB_FUZZ_SURFACER, surfacer_params()));
  const int strokes = 1 + b.byte() % 8;
  Vec3 first_start = Vec3::Zero();
  for (int k = 0; k < strokes && !b.empty(); ++k) {
    Stroke s;
    s.id = static_cast<StrokeId>(k + 1);
    s.layer = Layer::automatic;
    const int n = 1 + b.byte() % 48;
    Vec3 p = 0.5 * unit_vector(b) + Vec3(0, 1, 0);
    if (k == 0) first_start = p;
    for (int i = 0; i < n; ++i) {
      Sample smp;
      const std::uint8_t kind = b.byte();
      if (kind == 255) {
        smp.position = Vec3(b.number(1.0), b.number(1.0), b.number(1.0));
      } else {
        if (kind != 254 || i == 0) p += 0.025 * unit_vector(b);
        smp.position = p;
      }
      smp.time = session.last_time() + i / 90.0;
      smp.pressure = 0.7;
      s.samples.push_back(smp);
    }
    session.handle(Event{0.0, StrokeEvent{std::move(s)}});
  }
  if (b.flag()) session.handle(Event{0.0, DeleteNearEvent{first_start, 0.05}});
  if (b.flag()) session.handle(Event{0.0, UndoEvent{}});
  if (b.flag()) session.handle(Event{0.0, AddPatchEvent{first_start + 0.1 * unit_vector(b)}});
  return 0;
}
