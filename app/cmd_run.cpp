// `sketchlab run [EXPERIMENT.yaml] [key.path=value ...]`: replay each
// recording through each stack and write the results.
#include <iostream>

#include "commands.hpp"
#include "default_paths.hpp"
#include "sketchlab/config/config.hpp"
#include "sketchlab/io/mesh_export.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/io/stroke_csv.hpp"
#include "sketchlab/io/text_file.hpp"
#include "sketchlab/run/stack.hpp"

namespace sketchlab::cli {
namespace {

struct RunOptions {
  std::string experiment;
  std::vector<std::string> overrides;
  bool no_timings = false;
};

// Runs one (recording, stack) case; returns false if it failed.
bool run_case(const ExperimentConfig& config, const StackConfig& stack_config,
              const PluginHost& host, const std::filesystem::path& recording, bool timings) {
  const std::string label = recording.stem().string() + " x " + stack_config.name;
  try {
    const StackInstance stack = instantiate_stack(stack_config, host);
    auto input = instantiate_input(stack_config, host, recording);
    const ReplayResult result = replay(*input, stack);
    const auto dir = config.outputs.dir / config.name / recording.stem() / stack_config.name;
    const Sketch& sketch = result.session.sketch();
    if (config.outputs.sketch_json)
      write_text_file(dir / "sketch.json", sketch_to_json(sketch, &result.steps));
    if (config.outputs.stroke_csv)
      write_text_file(dir / "strokes.csv", steps_to_csv(result.steps, timings));
    if (config.outputs.ply) write_text_file(dir / "sketch.ply", network_to_ply(sketch.network));
    if (config.outputs.obj) write_text_file(dir / "sketch.obj", network_to_obj(sketch.network));
    int errors = 0;
    for (const auto& s : result.steps) errors += !s.error.empty();
    std::cout << label << ": " << result.steps.size() << " events, " << sketch.network.curves().size()
              << " curves, " << sketch.network.nodes().size() << " nodes, "
              << sketch.network.patches().size() << " patches, " << errors
              << " events refused -> " << dir.string() << "\n";
    return true;
  } catch (const std::exception& e) {
    std::cerr << label << ": FAILED: " << e.what() << "\n";
    return false;
  }
}

}  // namespace

void add_run_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "run", "Replay each recording of an experiment through each stack and write, per case, the "
             "final sketch (JSON) and per-event statistics (CSV)");
  auto opts = std::make_shared<RunOptions>();
  cmd->add_option("experiment", opts->experiment,
                  "Experiment YAML (default: the bundled configs/default.yaml)");
  cmd->add_option("overrides", opts->overrides,
                  "Overrides key.path=value, e.g. outputs.dir=/tmp/out "
                  "stacks.0.corrector.params.delta=0.03");
  cmd->add_flag("--no-timings", opts->no_timings,
                "Write latencies as 0 so repeated runs give byte-identical files");
  cmd->callback([opts, &exit_code] {
    std::vector<Override> overrides;
    std::string experiment = opts->experiment;
    // CLI11 cannot tell an override from the experiment path: a first
    // positional containing '=' is an override.
    if (experiment.find('=') != std::string::npos) {
      opts->overrides.insert(opts->overrides.begin(), experiment);
      experiment.clear();
    }
    for (const auto& o : opts->overrides) overrides.push_back(parse_override(o));
    const auto path = experiment.empty() ? default_experiment() : std::filesystem::path(experiment);
    const ExperimentConfig config = load_experiment(path, overrides);

    PluginHost host;
    host.load_directories(PluginHost::default_search_paths());
    for (const auto& e : host.errors())
      std::cerr << "warning: plugin " << e.path.string() << " not loaded: " << e.reason << "\n";

    int failed = 0;
    for (const auto& recording : config.recordings)
      for (const auto& stack : config.stacks)
        failed += !run_case(config, stack, host, recording, !opts->no_timings);
    const auto total = config.recordings.size() * config.stacks.size();
    std::cout << (total - failed) << " of " << total << " cases done";
    if (failed) std::cout << ", " << failed << " failed";
    std::cout << "\n";
    exit_code = failed ? 1 : 0;
  });
}

}  // namespace sketchlab::cli
