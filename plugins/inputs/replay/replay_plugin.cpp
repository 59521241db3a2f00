// Plays a recording file back, event by event (strokes, undo/redo, deletions,
// workspace changes, references). The whole file is read and checked when the
// input is created, so a malformed recording fails before anything runs,
// with file:line.
#include "sketchlab/plugin/param_table.hpp"
#include "sketchlab/plugin/plugin_api.hpp"
#include "sketchlab/plugin/recording_input.hpp"
#include "sketchlab/recording/recording_reader.hpp"

namespace {

using namespace sketchlab;

struct ReplaySettings {
  std::string path;
  std::int64_t max_events = -1;
  bool refuse_truncated = false;
};

const ParamTable<ReplaySettings>& parameters() {
  using R = ReplaySettings;
  static const auto table =
      ParamTable<R>()
          .string("path", &R::path, "recording file (JSON Lines) to play")
          .integer("max_events", &R::max_events, -1, {}, "", "stop after this many events (-1: play all)")
          .choice("partial_last_line", &R::refuse_truncated,
                  std::vector<std::pair<std::string, bool>>{{"skip", false}, {"refuse", true}},
                  "a last line without its newline (left by an interrupted write): skip it with a warning, "
                  "or refuse the recording");
  return table;
}

// The whole file is read (and checked) up front; max_events truncates it.
Recording read_truncated(const ReplaySettings& settings) {
  RecordingReadOptions options;
  options.refuse_truncated = settings.refuse_truncated;
  Recording recording = read_recording(settings.path, options);
  const auto limit = settings.max_events;
  if (limit >= 0 && static_cast<std::size_t>(limit) < recording.events.size())
    recording.events.resize(static_cast<std::size_t>(limit));
  return recording;
}

class ReplayInput : public RecordingInput {
 public:
  explicit ReplayInput(const Params& p) : RecordingInput(read_truncated(parameters().read(p))) {}
};

PluginDescriptor describe() {
  PluginDescriptor d = input_descriptor<ReplayInput>("replay", "1.0", "plays a recorded session (JSON Lines)",
                                                     parameters().specs());
  d.recording_param = "path";
  return d;
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
