// `sketchlab vr CONFIG [key=value ...] [-o REC.jsonl] [--sketch OUT.json]`:
// draw in VR with the stack (or the experiment's stacks) CONFIG (built with
// viewers/openxr only).
#include <iostream>

#include "commands.hpp"
#include "plugin_arguments.hpp"
#include "sketchlab/vr/vr_app.hpp"

namespace sketchlab::cli {

void add_vr_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<vr::VrOptions>();
  auto config = std::make_shared<std::string>();
  auto recording = std::make_shared<std::string>();
  auto sketch = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand(
      "vr", "Draw in VR (OpenXR headset) with a plugin stack; the session is recorded as it goes");
  cmd->add_option("config", *config,
                  "Stack file (YAML), e.g. configs/stacks/cassie.yaml, or an experiment (its stacks are switched "
                  "and compared from the hand menu), e.g. configs/compare.yaml")
      ->required();
  cmd->add_option("overrides", options->overrides, "Config overrides key.path=value");
  cmd->add_option("-o,--output", *recording, "Recording to write (default vr-<UTC time>.jsonl)");
  cmd->add_flag("--overwrite", options->overwrite, "Replace the recording if it exists");
  cmd->add_option("--sketch", *sketch, "Also write the final sketch (JSON, the first stack's) here");
  cmd->add_option("--grid", options->grid_spacing, "Workspace grid spacing in metres (shown near the hand; 0: off)");
  cmd->add_flag("--mirror", options->mirror, "Mirror plane x = 0 in the workspace");
  cmd->footer(
      "Needs an OpenXR runtime (Monado, SteamVR): set XR_RUNTIME_JSON to its manifest when it is not "
      "the active runtime. Replay the recording with `sketchlab run` or the desktop viewer.");
  cmd->callback([options, config, recording, sketch, &exit_code] {
    options->config = *config;
    options->recording = *recording;
    options->sketch = *sketch;
    PluginHost host;
    load_plugins(host);
    exit_code = vr::run_vr(*options, host, std::cout, std::cerr);
  });
}

}  // namespace sketchlab::cli
