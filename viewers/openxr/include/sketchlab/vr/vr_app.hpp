#pragma once
// `sketchlab vr CONFIG`: draw in VR with a plugin stack. The session is an
// OpenXR session (see viewers/openxr/README section in the top-level
// README), the controllers read by a controller input plugin (the openxr
// input, made through `host`: sketchlab/plugin/controller_input.hpp),
// correction on a worker thread, every event recorded (append + flush)
// before it is corrected.
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "sketchlab/plugin/plugin_host.hpp"

namespace sketchlab::vr {

struct VrOptions {
  std::filesystem::path config;         // stack file, or experiment whose stacks all run (YAML)
  std::vector<std::string> overrides;   // "key.path=value"
  std::filesystem::path recording;      // empty: vr-<UTC timestamp>.jsonl
  bool overwrite = false;
  std::filesystem::path sketch;         // optional: final sketch JSON of the first stack
  // The session's starting workspace (recorded in the header): grid spacing
  // in metres (0: no grid) and the mirror plane x = 0.
  double grid_spacing = 0.0;
  bool mirror = false;
};

// Figures of a finished session (render thread).
struct VrStats {
  std::size_t frames = 0;  // frames rendered
  int eye_width = 0, eye_height = 0;
  double frame_mean_ms = 0, frame_p95_ms = 0, frame_max_ms = 0;  // input + scene + both eyes
  std::size_t events = 0;
};

// Runs the session until the runtime ends it (or Ctrl-C). Returns the exit
// code (0, or 1 when the session was lost; the recording keeps what was
// drawn). Throws std::runtime_error (ConfigError, openxr::XrError, ...)
// with one readable message on failures before the session runs: bad
// config, recording exists, no X display, no OpenXR runtime, no headset,
// missing extension, session refused.
int run_vr(const VrOptions& options, const PluginHost& host, std::ostream& out, std::ostream& err,
           VrStats* stats = nullptr);

}  // namespace sketchlab::vr
