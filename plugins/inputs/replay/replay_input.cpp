// Plays a recording file back, event by event (strokes, undo/redo, deletions,
// workspace changes, references). The whole file is read and checked when the
// input is created, so a malformed recording fails before anything runs,
// with file:line.
#include "sketchlab/plugin/plugin_api.hpp"
#include "sketchlab/recording/recording_reader.hpp"

namespace {

using namespace sketchlab;

class ReplayInput : public Input {
 public:
  explicit ReplayInput(const Params& p) : recording_(read_recording(p.string("path"))) {
    const auto limit = p.integer("max_events");
    if (limit >= 0 && static_cast<std::size_t>(limit) < recording_.events.size())
      recording_.events.resize(static_cast<std::size_t>(limit));
  }
  RecordingHeader header() const override { return recording_.header; }
  std::optional<Event> next() override {
    if (finished()) return std::nullopt;
    return recording_.events[next_++];
  }
  bool finished() const override { return next_ >= recording_.events.size(); }

 private:
  Recording recording_;
  std::size_t next_ = 0;
};

PluginDescriptor describe() {
  std::vector<ParamSpec> specs{
      {"path", ParamType::string, std::string(), {}, {}, {}, "",
       "recording file (JSON Lines) to play"},
      {"max_events", ParamType::integer, std::int64_t{-1}, -1, {}, {}, "",
       "stop after this many events (-1: play all)"},
  };
  return input_descriptor<ReplayInput>("replay", "1.0", "plays a recorded session (JSON Lines)",
                                       std::move(specs));
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
