// A live session records every event before folding it, and its recording
// replays to the same sketches.
#include "sketchlab/lab/live_session.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "session_fixtures.hpp"
#include "sketchlab/recording/recording_reader.hpp"

namespace {

using namespace sketchlab;
using test::FitCorrector;
using test::sampled_stroke;

Stroke arc_stroke(StrokeId id, double y) {
  return sampled_stroke(id, 25, id, 0.01, [&](int i) -> Vec3 { return Vec3(0.01 * i, y + 0.002 * std::sin(i), 0.0); });
}

std::filesystem::path temp_recording(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / "sketchlab_live_session_test";
  std::filesystem::create_directories(dir);
  auto path = dir / name;
  std::filesystem::remove(path);
  return path;
}

std::vector<StackInstance> two_stacks() {
  auto fit = std::make_shared<FitCorrector>();
  return {StackInstance{"a", fit, nullptr}, StackInstance{"b", fit, nullptr}};
}

}  // namespace

TEST_CASE("a live session's recording replays to the same sketch", "[session]") {
  const auto path = temp_recording("replays.jsonl");
  RecordingHeader header;
  header.source["input"] = "test";
  LiveSession live(header, two_stacks(), path);
  live.handle(Event{1.0, StrokeEvent{arc_stroke(1, 0.0)}});
  live.handle(Event{2.0, StrokeEvent{arc_stroke(2, 0.1)}});
  live.handle(Event{3.0, UndoEvent{}});
  live.handle(Event{4.0, RedoEvent{}});
  // Each line is on disk as soon as it is handled, before close().
  const Recording on_disk = read_recording(path);
  CHECK(on_disk.header == header);
  REQUIRE(on_disk.events.size() == 4);
  CHECK(live.events_recorded() == 4);

  Session replayed(on_disk.header.workspace, live.stack(0).corrector, nullptr);
  for (const auto& e : on_disk.events) replayed.handle(e);
  CHECK(replayed.sketch() == live.session(0).sketch());
  CHECK(live.session(1).sketch() == live.session(0).sketch());
}

TEST_CASE("an event the recording refuses changes nothing", "[session]") {
  const auto path = temp_recording("refused.jsonl");
  LiveSession live({}, two_stacks(), path);
  live.handle(Event{5.0, StrokeEvent{arc_stroke(1, 0.0)}});
  const Sketch before = live.session(0).sketch();
  CHECK_THROWS_AS(live.handle(Event{4.0, StrokeEvent{arc_stroke(2, 0.1)}}), std::invalid_argument);
  CHECK(live.session(0).sketch() == before);
  CHECK(read_recording(path).events.size() == 1);
}

TEST_CASE("a live session refuses to overwrite a recording or run without stacks",
          "[session]") {
  const auto path = temp_recording("existing.jsonl");
  { LiveSession first({}, two_stacks(), path); }
  CHECK_THROWS_AS(LiveSession({}, two_stacks(), path), std::runtime_error);
  CHECK_THROWS_AS(LiveSession({}, {}, temp_recording("none.jsonl")), std::invalid_argument);
}
