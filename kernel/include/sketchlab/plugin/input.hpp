#pragma once
// Input plugins produce the event stream of a session.
#include <cassert>
#include <optional>
#include <string>
#include <utility>

#include "sketchlab/event.hpp"

namespace sketchlab {

// What Input::next() gives: an event, nothing yet (a live input: ask again
// later), or the end of the input (nothing will follow). Converts to true
// only when it holds an event, so `while (auto e = input.next())` reads the
// events ready now.
class NextEvent {
 public:
  enum class State { event, not_ready, ended };
  NextEvent(Event event) : state_(State::event), event_(std::move(event)) {}  // NOLINT: implicit by design
  static NextEvent not_ready() { return NextEvent(State::not_ready); }
  static NextEvent ended() { return NextEvent(State::ended); }

  State state() const { return state_; }
  bool has_event() const { return state_ == State::event; }
  bool is_ended() const { return state_ == State::ended; }
  explicit operator bool() const { return has_event(); }
  // The event; only when has_event().
  Event& operator*() { assert(event_); return *event_; }
  const Event& operator*() const { assert(event_); return *event_; }
  Event* operator->() { return &**this; }
  const Event* operator->() const { return &**this; }

 private:
  explicit NextEvent(State state) : state_(state) {}
  State state_;
  std::optional<Event> event_;
};

class Input {
 public:
  virtual ~Input() = default;
  // Header of the session (workspace at start, units, provenance).
  virtual RecordingHeader header() const = 0;
  // The next event; NextEvent::not_ready() when a live input has nothing yet
  // (ask again later), NextEvent::ended() once the input has ended, for good:
  // every later call ends too. An input that fails ends (see error()).
  virtual NextEvent next() = 0;
  // Non-empty once the input failed (device lost, unreadable file); next()
  // then ends. Events already returned stay valid.
  virtual std::string error() const { return {}; }
  // Asks a live input to end (the user stopped the command): it finishes what
  // is in progress (a stroke being drawn comes out as an event) and then
  // ends. Inputs that end by themselves ignore it.
  virtual void request_stop() {}
};

}  // namespace sketchlab
