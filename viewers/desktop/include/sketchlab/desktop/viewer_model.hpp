#pragma once
// What the desktop window shows, without any windowing: the stacks, a replay
// of an opened recording, and the live session that takes over when the
// user draws or edits.
//
// Invariant: events() is exactly what every shown sketch is the fold of.
// While replaying that is the recording's prefix up to the replay position;
// once live, the live recording file holds events() (append + flush per
// event, LiveSession), so `sketchlab run` on it reproduces every sketch.
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "sketchlab/desktop/replay_controller.hpp"
#include "sketchlab/lab/live_session.hpp"

namespace sketchlab::desktop {

class ViewerModel {
 public:
  // `replay` may be null (start live). `live_header` is the header of a live
  // session started from scratch (with a replay, its header is kept).
  // The live recording is created at `record_path` on the first live event.
  ViewerModel(std::vector<StackInstance> stacks, std::optional<Recording> replay,
              RecordingHeader live_header, std::filesystem::path record_path,
              bool overwrite = false);

  std::size_t stack_count() const { return stacks_.size(); }
  const std::string& stack_name(std::size_t i) const { return stacks_.at(i).name; }
  const Sketch& sketch(std::size_t stack) const;
  const StepReport* last_stroke_report(std::size_t stack) const;

  // Null once the session is live.
  ReplayController* replay() { return live_ ? nullptr : replay_.get(); }
  bool live() const { return live_ != nullptr; }

  // Records and folds one event (user input). The first one starts the live
  // session: the replayed prefix is written to the new recording and folded
  // again, then the event follows. Throws what LiveSession::handle throws.
  std::vector<StepReport> handle_live(const Event& event);

  // Every event the sketches are the fold of, with the header.
  Recording events() const;
  // Time of the last event in events() (0 when none).
  double last_time() const;
  // The first stroke id not used in events().
  StrokeId next_stroke_id() const;
  const std::filesystem::path& record_path() const { return record_path_; }

 private:
  std::vector<StackInstance> stacks_;
  std::unique_ptr<ReplayController> replay_;
  RecordingHeader live_header_;
  std::filesystem::path record_path_;
  bool overwrite_ = false;
  std::unique_ptr<LiveSession> live_;
  std::vector<Event> live_events_;
  std::vector<std::optional<StepReport>> live_reports_;
};

}  // namespace sketchlab::desktop
