#pragma once
// An input that plays a recording held in memory, event by event: the base
// of inputs that load or generate a whole session up front (replay,
// synthetic).
#include <cstddef>

#include "sketchlab/plugin/input.hpp"
#include "sketchlab/recording/recording.hpp"

namespace sketchlab {

class RecordingInput : public Input {
 public:
  explicit RecordingInput(Recording recording) : recording_(std::move(recording)) {}
  RecordingHeader header() const override { return recording_.header; }
  NextEvent next() override {
    if (next_ >= recording_.events.size()) return NextEvent::ended();
    return recording_.events[next_++];
  }

 private:
  Recording recording_;
  std::size_t next_ = 0;
};

}  // namespace sketchlab
