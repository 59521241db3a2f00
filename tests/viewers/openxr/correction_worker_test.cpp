// The VR viewer's correction worker: a slow corrector never blocks the
// thread that submits events (the render loop); the result appears when
// ready, and the recording is the same as handling the events inline.
#include <catch2/catch.hpp>

// Only when the VR viewer is built (its internals are on the include path).
#if __has_include("correction_worker.hpp")

#include <chrono>
#include <filesystem>
#include <thread>
#include <unistd.h>

#include "correction_worker.hpp"
#include "session_fixtures.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/recording/recording_reader.hpp"

using namespace sketchlab;
namespace fs = std::filesystem;

namespace {

// The freehand fit, `ms` milliseconds late.
class SlowCorrector : public test::FitCorrector {
 public:
  explicit SlowCorrector(int ms) : ms_(ms) {}
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    std::this_thread::sleep_for(std::chrono::milliseconds(ms_));
    return FitCorrector::correct(stroke, sketch);
  }

 private:
  int ms_;
};

// The fit, reporting one enforced snap at the stroke's start.
class SnappingCorrector : public test::FitCorrector {
 public:
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    Correction c = FitCorrector::correct(stroke, sketch);
    Constraint snap;
    snap.kind = ConstraintKind::coincident_point;
    snap.target = stroke.samples.front().position;
    snap.enforced = true;
    c.constraints.push_back(snap);
    return c;
  }
};

Event stroke_event(StrokeId id, double y) {
  const Stroke s = test::sampled_stroke(id, 10, 0.1 * id, 0.001, [&](int i) -> Vec3 { return Vec3(0.02 * i, y, 0.0); });
  return {0.1 * id + 0.01, StrokeEvent{s}};
}

}  // namespace

TEST_CASE("a slow corrector does not block submission, and results appear when ready", "[openxr]") {
  const fs::path rec = fs::temp_directory_path() / ("sketchlab_worker_" + std::to_string(getpid()) + ".jsonl");
  auto live = std::make_unique<LiveSession>(RecordingHeader{},
                                            std::vector<StackInstance>{{"slow", std::make_shared<SlowCorrector>(300), nullptr}},
                                            rec, true);
  vr::CorrectionWorker worker(std::move(live));
  const auto before = worker.latest();
  const auto t0 = std::chrono::steady_clock::now();
  for (StrokeId id = 1; id <= 3; ++id) worker.submit(stroke_event(id, 0.1 * id));
  const double submit_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  CHECK(submit_ms < 100.0);  // three corrections take 900 ms
  CHECK(worker.latest()->version == before->version);  // nothing finished yet
  CHECK(worker.latest()->stacks.at(0).sketch.network.curves().empty());
  const auto final_snapshot = worker.finish();
  CHECK(final_snapshot->events == 3);
  CHECK(final_snapshot->stacks.at(0).sketch.network.curves().size() == 3);
  CHECK(worker.problems().empty());
  // Recorded before corrected, in order: the file replays to the same sketch.
  const Recording recording = read_recording(rec);
  REQUIRE(recording.events.size() == 3);
  Session inline_session(Workspace{}, std::make_shared<SlowCorrector>(0), nullptr);
  for (const auto& e : recording.events) inline_session.handle(e);
  CHECK(sketch_to_json(inline_session.sketch()) == sketch_to_json(final_snapshot->stacks.at(0).sketch));
  fs::remove(rec);
}

TEST_CASE("snapshots carry every stack's sketch and what its corrector did with the latest stroke", "[openxr]") {
  const fs::path rec = fs::temp_directory_path() / ("sketchlab_worker_two_" + std::to_string(getpid()) + ".jsonl");
  auto live = std::make_unique<LiveSession>(
      RecordingHeader{},
      std::vector<StackInstance>{{"snap", std::make_shared<SnappingCorrector>(), nullptr},
                                 {"fit", std::make_shared<SlowCorrector>(0), nullptr}},
      rec, true);
  vr::CorrectionWorker worker(std::move(live));
  CHECK(worker.latest()->stacks.size() == 2);
  CHECK(worker.latest()->strokes == 0);
  worker.submit(stroke_event(1, 0.1));
  worker.submit(stroke_event(2, 0.2));
  worker.submit({1.0, UndoEvent{}});
  const auto last = worker.finish();
  REQUIRE(last->stacks.size() == 2);
  CHECK(last->strokes == 2);
  CHECK(last->stroke == StrokeId{2});
  REQUIRE(last->stacks[0].constraints.size() == 1);
  CHECK(last->stacks[0].constraints[0].enforced);
  CHECK((last->stacks[0].constraints[0].target - Vec3(0.0, 0.2, 0.0)).norm() < 1e-12);
  CHECK(last->stacks[1].constraints.empty());
  CHECK(last->stacks[0].sketch.network.curves().size() == 1);  // the undo took stroke 2 back
  CHECK(last->stacks[1].sketch.network.curves().size() == 1);
  fs::remove(rec);
}

TEST_CASE("an event the recording refuses is reported, not fatal", "[openxr]") {
  const fs::path rec = fs::temp_directory_path() / ("sketchlab_worker_bad_" + std::to_string(getpid()) + ".jsonl");
  auto live = std::make_unique<LiveSession>(RecordingHeader{},
                                            std::vector<StackInstance>{{"fast", std::make_shared<SlowCorrector>(0), nullptr}},
                                            rec, true);
  vr::CorrectionWorker worker(std::move(live));
  worker.submit(stroke_event(1, 0.1));
  worker.submit({0.0, UndoEvent{}});  // earlier than the stroke: refused
  worker.submit({1.0, UndoEvent{}});
  const auto last = worker.finish();
  REQUIRE(worker.problems().size() == 1);
  CHECK_THAT(worker.problems()[0], Catch::Contains("undo") && Catch::Contains("not recorded"));
  CHECK(last->events == 2);
  CHECK(read_recording(rec).events.size() == 2);
  fs::remove(rec);
}

TEST_CASE("the worker prepares each snapshot on its thread, and a failing prepare is reported with the last good snapshot kept",
          "[openxr]") {
  const fs::path rec = fs::temp_directory_path() / ("sketchlab_worker_prep_" + std::to_string(getpid()) + ".jsonl");
  auto live = std::make_unique<LiveSession>(RecordingHeader{},
                                            std::vector<StackInstance>{{"fast", std::make_shared<SlowCorrector>(0), nullptr}},
                                            rec, true);
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::thread::id> threads;  // read after finish()
  vr::CorrectionWorker worker(std::move(live), [&](vr::SketchSnapshot& snap) {
    threads.push_back(std::this_thread::get_id());
    if (snap.stacks.at(0).sketch.network.curves().size() > 1) throw std::runtime_error("out of memory");
    snap.geometry.push_back(std::make_shared<viewer::SketchGeometry>());
  });
  CHECK(worker.latest()->geometry.size() == 1);
  worker.submit(stroke_event(1, 0.1));
  while (worker.latest()->events < 1) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  worker.submit(stroke_event(2, 0.2));
  const auto last = worker.finish();
  CHECK(last->events == 1);  // the second snapshot failed: the first stays
  CHECK(last->geometry.size() == 1);
  REQUIRE(worker.problems().size() == 1);
  CHECK_THAT(worker.problems()[0], Catch::Contains("preparing the view after stroke") && Catch::Contains("out of memory"));
  REQUIRE(threads.size() == 3);
  CHECK(threads[0] == caller);
  CHECK(threads[1] != caller);
  CHECK(threads[2] == threads[1]);
  CHECK(read_recording(rec).events.size() == 2);  // recorded all the same
  fs::remove(rec);
}

#endif
