#include <catch2/catch.hpp>
#include <filesystem>
#include <set>

#include "sketchlab/lab/cassie_import.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/session.hpp"
#include "test_paths.hpp"

using namespace sketchlab;

namespace {

// data/recordings/<name>.jsonl, or the same session imported from data/cassie
// when the converted recordings are not there.
Recording load_session(const std::string& name) {
  const auto path = test::source_path("data/recordings/" + name + ".jsonl");
  if (std::filesystem::exists(path)) return read_recording(path);
  return import_cassie_session(test::source_path("data/cassie"), name);
}

}  // namespace

TEST_CASE("The cassie plugin loads through the PluginHost and replays hat", "[cassie][plugin]") {
  PluginHost host;
  host.load_directories({SKETCHLAB_BUILD_PLUGIN_DIR});
  const LoadedPlugin* p = host.find(PluginKind::corrector, "cassie");
  REQUIRE(p);
  CHECK(p->descriptor->params.size() > 10);
  auto corrector = host.make_corrector("cassie", {{"mirror", std::string("plane")}});
  REQUIRE(corrector);
  CHECK_THROWS(host.make_corrector("cassie", {{"lambda", 2.0}}));

  const Recording rec = load_session("hat");
  Session session(rec.header.workspace, corrector, nullptr);
  std::set<StrokeId> alive;
  int errors = 0, strokes = 0, with_constraints = 0;
  for (const Event& e : rec.events) {
    const StepReport r = session.handle(e);
    if (!r.error.empty()) {
      ++errors;
      UNSCOPED_INFO("event at " << e.time << ": " << r.error);
    }
    if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) {
      alive.insert(s->stroke.id);
      ++strokes;
      with_constraints += r.stats.subsets_tried > 0;
    }
    if (const auto* d = std::get_if<DeleteStrokeEvent>(&e.payload)) alive.erase(d->stroke);
  }
  CHECK(errors == 0);
  CHECK(strokes == 143);
  CHECK(with_constraints > 0);
  for (StrokeId id : alive) {
    INFO("stroke " << id);
    CHECK_FALSE(curves_of_stroke(session.sketch(), id).empty());
  }
  CHECK(!session.sketch().network.nodes().empty());
}
