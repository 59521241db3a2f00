// Plays a recording file back, event by event (strokes, undo/redo, deletions,
// workspace changes, references). The whole file is read and checked when the
// input is created, so a malformed recording fails before anything runs,
// with file:line.
#include "sketchlab/plugin/plugin_api.hpp"
#include "sketchlab/plugin/recording_input.hpp"
#include "sketchlab/recording/recording_reader.hpp"

namespace {

using namespace sketchlab;

// The whole file is read (and checked) up front; max_events truncates it.
Recording read_truncated(const Params& p) {
  RecordingReadOptions options;
  options.refuse_truncated = p.string("partial_last_line") == "refuse";
  Recording recording = read_recording(p.string("path"), options);
  const auto limit = p.integer("max_events");
  if (limit >= 0 && static_cast<std::size_t>(limit) < recording.events.size())
    recording.events.resize(static_cast<std::size_t>(limit));
  return recording;
}

class ReplayInput : public RecordingInput {
 public:
  explicit ReplayInput(const Params& p) : RecordingInput(read_truncated(p)) {}
};

PluginDescriptor describe() {
  std::vector<ParamSpec> specs{
      {"path", ParamType::string, std::string(), {}, {}, {}, "",
       "recording file (JSON Lines) to play"},
      {"max_events", ParamType::integer, std::int64_t{-1}, -1, {}, {}, "",
       "stop after this many events (-1: play all)"},
      {"partial_last_line", ParamType::choice, std::string("skip"), {}, {}, {"skip", "refuse"}, "",
       "a last line without its newline (left by an interrupted write): skip it with a warning, "
       "or refuse the recording"},
  };
  PluginDescriptor d = input_descriptor<ReplayInput>("replay", "1.0", "plays a recorded session (JSON Lines)",
                                                     std::move(specs));
  d.recording_param = "path";
  return d;
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
