#pragma once
// Runs a LiveSession on its own thread so that correction never blocks the
// render loop: the render thread submits events and draws the latest sketch
// the worker finished; a slow plugin delays the result, never a frame.
//
// Events are handled in submission order (the recording and the fold are
// the same as handling them inline); each is appended + flushed by the
// LiveSession before the stacks see it.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "sketch_geometry.hpp"
#include "sketchlab/lab/live_session.hpp"

namespace sketchlab::vr {

// One stack's picture: its sketch and what its corrector considered for the
// latest stroke (the StepReport's constraints, `enforced` telling which held;
// empty when that stroke was not corrected).
struct StackSnapshot {
  Sketch sketch;
  std::vector<Constraint> constraints;
};

// What the render thread draws: every stack's sketch after `events` events.
struct SketchSnapshot {
  std::vector<StackSnapshot> stacks;  // in the session's stack order
  std::optional<StrokeId> stroke;     // the latest stroke event handled
  std::size_t strokes = 0;            // stroke events handled (a new one: a new correction to show)
  std::size_t events = 0;
  std::uint64_t version = 0;
  // Filled by the worker's `prepare` (the VR scene's: every stack's
  // drawable geometry, built on the worker; see vr_scene.hpp).
  std::vector<std::shared_ptr<const viewer::SketchGeometry>> geometry;
};

class CorrectionWorker {
 public:
  // Work done on every snapshot before the render thread sees it, on the
  // worker thread (and on the constructing thread for the first one).
  using Prepare = std::function<void(SketchSnapshot&)>;
  // Runs `live` (not null); `prepare` may be empty. An exception from
  // `prepare` on the worker is reported in problems() and that snapshot is
  // not published (the previous one stays); from the first snapshot's, the
  // constructor throws it.
  explicit CorrectionWorker(std::unique_ptr<LiveSession> live, Prepare prepare = {});
  ~CorrectionWorker();
  CorrectionWorker(const CorrectionWorker&) = delete;
  CorrectionWorker& operator=(const CorrectionWorker&) = delete;

  void submit(Event event);
  // Latest finished snapshot (never null).
  std::shared_ptr<const SketchSnapshot> latest() const;
  // Handles everything submitted, stops the thread and closes the recording.
  // Returns the final snapshot.
  std::shared_ptr<const SketchSnapshot> finish();
  // Problems met so far, one line each (refused events, plugin errors).
  std::vector<std::string> problems() const;
  const LiveSession& live() const { return *live_; }  // only after finish()

 private:
  void run();
  std::shared_ptr<const SketchSnapshot> snapshot(std::uint64_t version) const;
  std::unique_ptr<LiveSession> live_;
  Prepare prepare_;
  // Worker thread only: the latest stroke's constraints per stack.
  std::vector<std::vector<Constraint>> constraints_;
  std::optional<StrokeId> stroke_;
  std::size_t strokes_ = 0;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Event> queue_;
  bool stopping_ = false;
  std::shared_ptr<const SketchSnapshot> latest_;
  std::vector<std::string> problems_;
  std::thread thread_;
};

}  // namespace sketchlab::vr
