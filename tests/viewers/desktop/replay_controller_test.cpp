// Replay controls without a window: stepping back and forth over a bundled
// CASSIE session returns the identical sketch at every step.
#include <catch2/catch.hpp>

#include <filesystem>

#include "sketchlab/desktop/replay_controller.hpp"
#include "sketchlab/desktop/viewer_model.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/plugin/recording_input.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "stacks.hpp"

using namespace sketchlab;
using namespace sketchlab::desktop;

namespace {

// The first `n` events of `rec`, folded by a fresh session (no stepping).
Sketch fold_prefix(const Recording& rec, std::size_t n, const StackInstance& stack) {
  Session s(rec.header.workspace, stack.corrector, stack.surfacer);
  for (std::size_t i = 0; i < n; ++i) s.handle(rec.events[i]);
  return s.sketch();
}

}  // namespace

TEST_CASE("stepping forward and back over a CASSIE session gives identical sketches",
          "[desktop][replay]") {
  const Recording rec = read_recording(test::source_path("data/recordings/01-2-1.jsonl"));
  const auto stacks = test::compare_stacks();
  REQUIRE(stacks.size() == 2);
  ReplayController replay(rec, stacks);
  REQUIRE(replay.stroke_count() > 10);

  // Forward one stroke at a time, remembering every stack's sketch.
  std::vector<std::vector<Sketch>> forward(stacks.size());
  std::vector<std::size_t> positions;
  do {
    positions.push_back(replay.position());
    for (std::size_t s = 0; s < stacks.size(); ++s) forward[s].push_back(replay.session(s).sketch());
  } while (replay.step_forward());
  CHECK(replay.at_end());
  CHECK(positions.size() == replay.stops().size());
  for (std::size_t k = 1; k < positions.size(); ++k) CHECK(positions[k] > positions[k - 1]);

  // Back again, step by step: the same sketch at every stop.
  for (std::size_t k = positions.size(); k-- > 0;) {
    CHECK(replay.position() == positions[k]);
    for (std::size_t s = 0; s < stacks.size(); ++s)
      REQUIRE(replay.session(s).sketch() == forward[s][k]);
    const bool moved = replay.step_back();
    CHECK(moved == (k > 0));
  }

  // Scrubbing to arbitrary stops equals a fresh fold of that prefix.
  for (std::size_t stop : {std::size_t{7}, std::size_t{2}, positions.size() - 1, std::size_t{5}}) {
    replay.seek_stop(stop);
    CHECK(replay.stop_index() == stop);
    for (std::size_t s = 0; s < stacks.size(); ++s) {
      CHECK(replay.session(s).sketch() == forward[s][stop]);
      CHECK(sketch_to_json(replay.session(s).sketch()) ==
            sketch_to_json(fold_prefix(rec, replay.position(), stacks[s])));
    }
  }
}

TEST_CASE("a live session continuing a replay records the prefix and replays exactly",
          "[desktop][live]") {
  const Recording rec = read_recording(test::source_path("data/recordings/01-2-1.jsonl"));
  const auto stacks = test::compare_stacks();
  const auto dir = std::filesystem::temp_directory_path() / "sketchlab_viewer_model_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto file = dir / "live.jsonl";

  ViewerModel model(stacks, rec, rec.header, file);
  model.replay()->seek_stop(4);
  const std::size_t prefix = model.replay()->position();
  const StrokeId next = model.next_stroke_id();
  CHECK(!model.live());
  CHECK(!std::filesystem::exists(file));  // nothing recorded before the first live event

  // A user stroke (3D, as a VR pen would give) and an undo.
  Stroke s;
  s.id = next;
  for (int i = 0; i < 10; ++i) {
    Sample x;
    x.position = Vec3(0.1 * i, 1.0, 0.2);
    x.time = rec.events.back().time + 1 + 0.01 * i;
    s.samples.push_back(x);
  }
  model.handle_live(Event{s.samples.back().time, StrokeEvent{s}});
  model.handle_live(Event{s.samples.back().time + 1, UndoEvent{}});
  model.handle_live(Event{s.samples.back().time + 2, RedoEvent{}});
  REQUIRE(model.live());
  CHECK(model.replay() == nullptr);

  const Recording written = read_recording(file);
  CHECK(written == model.events());
  CHECK(written.events.size() == prefix + 3);
  for (std::size_t i = 0; i < prefix; ++i) CHECK(written.events[i] == rec.events[i]);

  // `sketchlab run`'s replay of the live file gives every stack's sketch.
  for (std::size_t k = 0; k < stacks.size(); ++k) {
    RecordingInput input(read_recording(file));
    const ReplayResult r = replay(input, stacks[k]);
    CHECK(sketch_to_json(r.session.sketch()) == sketch_to_json(model.sketch(k)));
  }
  CHECK(!model.sketch(0).network.curves().empty());
  std::filesystem::remove_all(dir);
}
