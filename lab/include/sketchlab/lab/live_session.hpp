#pragma once
// A live drawing session (tablet, mouse, VR): every event goes to the
// recording first, then to every stack of the session.
//
// Invariant: the recording on disk holds exactly the events handled so far,
// each line flushed before the stacks see it, so a crash loses nothing that
// was drawn, and `sketchlab run` on the recording reproduces every stack's
// sketch bit for bit (the fold is deterministic, see session.hpp).
#include <cstddef>
#include <filesystem>
#include <vector>

#include "sketchlab/lab/stack.hpp"
#include "sketchlab/recording/recording_writer.hpp"
#include "sketchlab/session.hpp"

namespace sketchlab {

class LiveSession {
 public:
  // `stacks` must not be empty (std::invalid_argument). Creates `recording`
  // and writes `header`; throws std::runtime_error if the file exists (unless
  // overwrite) or cannot be written, before anything else happens.
  LiveSession(const RecordingHeader& header, std::vector<StackInstance> stacks,
              const std::filesystem::path& recording, bool overwrite = false);

  // Records `event` (append + flush), then folds it through every stack.
  // Returns one report per stack, in stack order. An event the recording
  // format refuses (non-finite values, time earlier than the previous event)
  // throws std::invalid_argument and changes nothing.
  std::vector<StepReport> handle(const Event& event);

  std::size_t stack_count() const { return stacks_.size(); }
  const StackInstance& stack(std::size_t i) const { return stacks_.at(i); }
  const Session& session(std::size_t i) const { return sessions_.at(i); }
  const RecordingHeader& header() const { return header_; }
  const std::filesystem::path& recording_path() const { return writer_.path(); }
  std::size_t events_recorded() const { return writer_.lines_written() - 1; }

  // Flushes and closes the recording; later events throw std::runtime_error.
  void close() { writer_.close(); }

 private:
  RecordingHeader header_;
  std::vector<StackInstance> stacks_;
  std::vector<Session> sessions_;
  RecordingWriter writer_;
};

}  // namespace sketchlab
