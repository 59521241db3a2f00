// The recordings that hung the stacks before issue 17
// (tests/fixtures/reliability/, from the reliability campaign), replayed
// through every stack they concern, event by event as `sketchlab run` does.
// Before: D3, a 10 km glitch sample (H1) or a 1e6 m line next to a 1 mm
// square (H1b) hung every world-space stack in the spatial index, and a draw
// plane containing the view rays (H4) hung JustDrawIt; D6, pixels near 1e6
// (H3) hung JustDrawIt and one 65535 px glitch (H3b) made it 14x slower.
// Now each event ends well within a second, nothing non-finite is written,
// and strokes that can be corrected are.
#include <catch2/catch.hpp>
#include <chrono>
#include <string>
#include <vector>

#include "build_plugin_host.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/session.hpp"
#include "test_paths.hpp"

using namespace sketchlab;

namespace {

// Far above what each event takes now (milliseconds in Release), far below
// the hangs (minutes) even under the sanitizers.
constexpr double event_limit_s = 5.0;

struct Replayed {
  std::vector<StepReport> steps;
  Sketch sketch;
};

Replayed replay(const std::string& fixture, const std::string& corrector, const std::string& surfacer) {
  const PluginHost& host = test::build_plugin_host();
  const Recording rec = read_recording(test::source_path("tests/fixtures/reliability/" + fixture));
  Session session(rec.header.workspace, host.make_corrector(corrector, {}),
                  surfacer.empty() ? nullptr : host.make_surfacer(surfacer, {}));
  Replayed out;
  for (const Event& e : rec.events) {
    const auto start = std::chrono::steady_clock::now();
    StepReport r;
    REQUIRE_NOTHROW(r = session.handle(e));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    INFO(fixture << " on " << corrector << "+" << surfacer << ", event " << out.steps.size() << ": "
                 << seconds << " s, error '" << r.error << "'");
    CHECK(seconds < event_limit_s);
    out.steps.push_back(r);
  }
  out.sketch = session.sketch();
  // sketch_to_json writes NaN and infinity as null.
  CHECK(sketch_to_json(out.sketch, &out.steps).find("null") == std::string::npos);
  return out;
}

std::vector<std::string> correctors_in(StrokeSpace space) {
  std::vector<std::string> names;
  const PluginHost& host = test::build_plugin_host();
  for (const auto& p : host.plugins())
    if (p.descriptor->kind == PluginKind::corrector && host.make_corrector(p.descriptor->name, {})->stroke_space() == space)
      names.push_back(p.descriptor->name);
  return names;
}

}  // namespace

TEST_CASE("D3: a glitch sample kilometres away no longer hangs the world-space stacks",
          "[adversarial][reliability]") {
  const auto correctors = correctors_in(StrokeSpace::world);
  REQUIRE(correctors.size() >= 3);  // freehand, cassie, scaffoldsketch
  for (const std::string fixture : {"H1_glitch_sample_10000m.jsonl", "H1b_huge_range_mix.jsonl"})
    for (const auto& c : correctors)
      for (const std::string s : {"", "soapfilm", "hermite_rbf"}) {
        const Replayed r = replay(fixture, c, s);
        std::size_t corrected = 0;
        for (const StepReport& step : r.steps) corrected += step.event == EventKind::stroke && step.error.empty();
        INFO(fixture << " on " << c << "+" << s);
        CHECK(corrected >= 3);
        CHECK(r.sketch.network.curves().size() >= 3);
      }
}

TEST_CASE("D6: JustDrawIt on far and glitching pixels ends at once", "[adversarial][reliability]") {
  // Every stroke jumps between (0, 0) and (1e6, -1e6) px: what is left on
  // screen is one point, refused with the reason.
  const Replayed far = replay("H3_justdrawit_far_pixels.jsonl", "justdrawit", "");
  for (const StepReport& step : far.steps) {
    INFO("stroke " << step.stroke.value_or(0));
    CHECK(step.error.find("zero length once its 10 samples far off screen") != std::string::npos);
  }
  // A square with one 65535 px spike: the spike is left out, the square drawn.
  const Replayed glitch = replay("H3b_justdrawit_glitch_65535px.jsonl", "justdrawit", "");
  std::size_t dropped = 0;
  for (const StepReport& step : glitch.steps) {
    INFO("stroke " << step.stroke.value_or(0) << ": '" << step.error << "'");
    CHECK(step.error.empty());
    if (step.stats.extra.count("offscreen_samples_dropped")) dropped += static_cast<std::size_t>(step.stats.extra.at("offscreen_samples_dropped"));
  }
  CHECK(dropped == 1);
}

TEST_CASE("D3: JustDrawIt refuses strokes on a draw plane containing the view rays", "[adversarial][reliability]") {
  const Replayed r = replay("H4_justdrawit_plane_parallel.jsonl", "justdrawit", "");
  for (const StepReport& step : r.steps) {
    if (step.event != EventKind::stroke) continue;
    INFO("stroke " << step.stroke.value_or(0));
    CHECK(step.error.find("ray misses the draw plane") != std::string::npos);
  }
  CHECK(r.sketch.network.curves().empty());
}
