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
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "sketchlab/run/live_session.hpp"

namespace sketchlab::vr {

// What the render thread draws: the shown stack's sketch after `events`
// events.
struct SketchSnapshot {
  Sketch sketch;
  std::size_t events = 0;
  std::uint64_t version = 0;
};

class CorrectionWorker {
 public:
  // Shows stack `shown` of `live` (must be < live->stack_count()).
  CorrectionWorker(std::unique_ptr<LiveSession> live, std::size_t shown);
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
  std::unique_ptr<LiveSession> live_;
  std::size_t shown_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Event> queue_;
  bool stopping_ = false;
  std::shared_ptr<const SketchSnapshot> latest_;
  std::vector<std::string> problems_;
  std::thread thread_;
};

}  // namespace sketchlab::vr
