#pragma once
// `sketchlab view`: the interactive desktop viewer (VTK-free interface).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sketchlab::desktop {

struct ViewOptions {
  // Experiment (its stacks) or stack YAML; empty: one freehand stack.
  std::filesystem::path config;
  std::vector<std::string> overrides;  // key.path=value, applied to the config
  std::optional<std::filesystem::path> recording;  // opened for replay
  // Live recording (append + flush per event), created on the first
  // stroke or command; default sketchlab-live-<UTC time>.jsonl.
  std::filesystem::path record;
  bool overwrite = false;
  std::filesystem::path save;        // `s` writes the events so far here (default <record>-saved.jsonl)
  std::filesystem::path export_dir = ".";  // `j` sketch JSON, `e` PLY/OBJ/.mlp, `p` screenshots
  int width = 1280, height = 720;
  int multisamples = 4;
  bool play = false;              // start playing the recording
  double play_interval = 0.35;    // seconds per stroke while playing
  std::optional<std::size_t> at_stroke;  // start the replay after this many strokes
  std::vector<std::filesystem::path> plugin_dirs;  // besides the default search paths
};

// The text of the help overlay (one key per line).
std::string help_text();

// Opens the window and runs until it is closed or `q`/Escape; returns the
// exit code. Throws std::runtime_error (no display, bad config, ...) before
// opening anything.
int run_view(const ViewOptions& options);

}  // namespace sketchlab::desktop
