#pragma once
// Replay controls over a recording folded through several stacks at once:
// play, step one stroke forward or back, scrub to any stroke. Stepping back
// is Session::revert_last (the inverse edits from the event log), never a
// re-fold or a re-render trick.
//
// Invariant: every session has handled exactly events [0, position()) of
// the recording, so each sketch equals the fold of that prefix.
#include <cstddef>
#include <vector>

#include "sketchlab/lab/stack.hpp"
#include "sketchlab/recording/recording.hpp"
#include "sketchlab/session.hpp"

namespace sketchlab::desktop {

class ReplayController {
 public:
  // `stacks` must not be empty (std::invalid_argument).
  ReplayController(Recording recording, const std::vector<StackInstance>& stacks);

  std::size_t position() const { return position_; }  // events handled
  std::size_t event_count() const { return recording_.events.size(); }
  // Stroke steps: 0 (nothing handled), then the position just after each
  // stroke event, and the end of the recording.
  const std::vector<std::size_t>& stops() const { return stops_; }
  // Index in stops() of the last stop at or before position().
  std::size_t stop_index() const;
  std::size_t stroke_count() const { return stops_.size() - 1; }

  // Handles / reverts events until position() == `event_index` (clamped).
  void seek(std::size_t event_index);
  void seek_stop(std::size_t stop);
  // One stroke forward / back; false at the end / start.
  bool step_forward();
  bool step_back();
  bool at_end() const { return position_ == recording_.events.size(); }

  std::size_t stack_count() const { return sessions_.size(); }
  const Session& session(std::size_t stack) const { return sessions_.at(stack); }
  // The report of the last handled stroke event of `stack` (null if none).
  const StepReport* last_stroke_report(std::size_t stack) const;
  const Recording& recording() const { return recording_; }

 private:
  Recording recording_;
  std::vector<Session> sessions_;
  std::vector<std::vector<StepReport>> reports_;  // per stack, one per handled event
  std::vector<std::size_t> stops_;
  std::size_t position_ = 0;
};

}  // namespace sketchlab::desktop
