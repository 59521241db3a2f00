#pragma once
// Input plugins produce the event stream of a session.
#include <optional>
#include <string>

#include "sketchlab/event.hpp"

namespace sketchlab {

class Input {
 public:
  virtual ~Input() = default;
  // Header of the session (workspace at start, units, provenance).
  virtual RecordingHeader header() const = 0;
  // Next event, or nullopt when the input has ended (replay) or has nothing
  // ready yet (live inputs: check finished()).
  virtual std::optional<Event> next() = 0;
  virtual bool finished() const = 0;
  // Non-empty once the input failed (device lost, unreadable file); it then
  // reports finished(). Events already returned stay valid.
  virtual std::string error() const { return {}; }
  // Asks a live input to end (the user stopped the command): it finishes what
  // is in progress (a stroke being drawn comes out as an event) and then
  // reports finished(). Inputs that end by themselves ignore it.
  virtual void request_stop() {}
};

}  // namespace sketchlab
