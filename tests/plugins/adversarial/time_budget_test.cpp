// Every corrector and surfacer with real work per stroke honours the
// per-event time budget (plugin/budget.hpp): run under an already spent
// budget, the bundled synthetic sessions' strokes come back with the budget
// error instead of a result, and a plugin that never checks would return
// results. Freehand is left out: its work is the kernel's preprocessing.
#include <catch2/catch.hpp>
#include <string>

#include "build_plugin_host.hpp"
#include "sketchlab/draw_plane.hpp"
#include "sketchlab/plugin/budget.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/session.hpp"
#include "test_paths.hpp"

using namespace sketchlab;

namespace {

const std::string spent = BudgetExceeded{1e-9}.message();

// Replays `recording` through `corrector` (normal budget); before each stroke
// the corrector is asked once more under a spent budget. Returns how many of
// those answers were the budget error.
int budget_errors(const std::string& corrector, const std::string& recording) {
  const PluginHost& host = test::build_plugin_host();
  auto c = host.make_corrector(corrector, {});
  const Recording rec = read_recording(test::source_path(recording));
  Session session(rec.header.workspace, c, nullptr);
  int errors = 0;
  for (const Event& e : rec.events) {
    if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) {
      std::string lift_error;
      const Stroke stroke =
          c->stroke_space() == StrokeSpace::pixels ? s->stroke : lift_to_draw_plane(s->stroke, lift_error);
      REQUIRE(lift_error.empty());
      Correction out;
      {
        const BudgetScope budget(1e-9);
        out = c->correct(stroke, session.sketch());
      }
      errors += out.error == spent;
    }
    session.handle(e);
  }
  return errors;
}

}  // namespace

TEST_CASE("correctors stop at their loop heads when the budget is spent", "[adversarial][budget]") {
  CHECK(budget_errors("cassie", "data/synthetic/mug.jsonl") > 0);
  CHECK(budget_errors("scaffoldsketch", "data/synthetic/cube.jsonl") > 0);
  CHECK(budget_errors("analytic", "data/synthetic/tablet/cube.jsonl") > 0);
  CHECK(budget_errors("justdrawit", "data/synthetic/tablet/cube.jsonl") > 0);
}

TEST_CASE("surfacers stop when the budget is spent", "[adversarial][budget]") {
  const PluginHost& host = test::build_plugin_host();
  // A real Patch-system session: CASSIE's rules close cycles there (on the
  // noisy synthetic cube its brush-radius snapping leaves the faces open).
  const Recording rec = read_recording(test::source_path("data/recordings/01-2-2.jsonl"));
  Session session(rec.header.workspace, host.make_corrector("cassie", {}), nullptr);
  int soapfilm_errors = 0;
  for (const Event& e : rec.events) {
    session.handle(e);
    const auto& done = session.sketch().history.done;
    if (done.empty() || done.back().steps.empty()) continue;
    // A fresh surfacer per question: it sees the sketch, not its own past.
    auto soapfilm = host.make_surfacer("soapfilm", {});
    const BudgetScope budget(1e-9);
    soapfilm_errors += soapfilm->update(session.sketch(), done.back().steps.back().forward).error == spent;
  }
  CHECK(soapfilm_errors > 0);

  auto rbf = host.make_surfacer("hermite_rbf", {});
  REQUIRE(rbf->recompute(session.sketch()).error.empty());
  const BudgetScope budget(1e-9);
  CHECK(rbf->recompute(session.sketch()).error == spent);
}
