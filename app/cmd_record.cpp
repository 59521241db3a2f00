// `sketchlab record --input NAME [--param k=v ...] -o FILE`: runs an input
// plugin to its end and writes what it produced as a recording, each event as
// it comes. Live inputs (openxr) are polled until they end; Ctrl-C or
// SIGTERM asks them to finish what is in progress and stops cleanly.
// `sketchlab synth MODEL [-o FILE] [--modality vr|tablet] [--noise X]
// [--seed N] [--param k=v ...]`: the same with the synthetic input (MODEL is
// a built-in model name, or an .off/.ply mesh whose feature curves to draw).
#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>
#include <thread>

#include "commands.hpp"
#include "plugin_arguments.hpp"
#include "sketchlab/lab/stop_signals.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "sketchlab/recording/recording_writer.hpp"

namespace sketchlab::cli {
namespace {

struct RecordOptions {
  std::string input;
  std::vector<std::string> params;
  std::string output;
  bool overwrite = false;
};

struct SynthOptions {
  std::string model;
  std::string output;
  std::optional<std::string> modality;
  std::optional<double> noise;
  std::optional<std::int64_t> seed;
  std::vector<std::string> params;
  bool overwrite = false;
};

// What a stopped input may still deliver (the stroke it was drawing) before
// the recording is closed without it.
constexpr std::chrono::seconds stop_grace{2};

// Runs the input to its end (or until a stop signal), writing each event as
// it comes. Returns the number of events written.
std::size_t record(const std::string& input_name, const std::vector<std::string>& texts,
                   const std::map<std::string, ParamValue>& extra, const std::string& output,
                   bool overwrite) {
  PluginHost host;
  load_plugins(host);
  const LoadedPlugin* plugin = host.find(PluginKind::input, input_name);
  std::map<std::string, ParamValue> params = extra;
  if (plugin)
    for (auto& [k, v] : parse_param_arguments(*plugin, texts)) params[k] = v;
  const auto input = host.make_input(input_name, params);  // throws for unknown names
  if (!overwrite && std::filesystem::exists(output))
    throw std::runtime_error(output + ": already exists; pass --overwrite to replace it");
  RecordingWriter writer(output, input->header(), overwrite);
  std::size_t events = 0;
  const StopSignals signals;
  std::optional<std::chrono::steady_clock::time_point> stop_by;
  bool live = false;
  for (;;) {
    if (StopSignals::stop_requested() && !stop_by) {
      std::cerr << "sketchlab record: stopping (signal " << StopSignals::received() << ")\n";
      input->request_stop();
      stop_by = std::chrono::steady_clock::now() + stop_grace;
    }
    if (stop_by && std::chrono::steady_clock::now() > *stop_by) break;
    NextEvent event = input->next();
    if (event.is_ended()) break;
    if (!event) {
      if (!live) {
        live = true;
        std::cerr << "sketchlab record: recording input '" << input_name << "' to " << output
                  << " (Ctrl-C stops)\n";
      }
      // A live input with nothing ready: it paces itself, this only keeps
      // one that does not from spinning.
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      continue;
    }
    writer.append(*event);
    ++events;
  }
  if (const std::string error = input->error(); !error.empty())
    throw std::runtime_error("input '" + input_name + "' failed after " + std::to_string(events) +
                             " events (kept in " + output + "): " + error);
  writer.close();
  return events;
}

}  // namespace

void add_record_command(CLI::App& app, int& exit_code) {
  auto ro = std::make_shared<RecordOptions>();
  auto* rec = app.add_subcommand("record", "Run an input plugin to its end and write a recording");
  rec->add_option("--input", ro->input, "Input plugin name (e.g. synthetic, replay)")->required();
  rec->add_option("--param", ro->params, "Input parameter key=value (repeatable)");
  rec->add_option("-o,--output", ro->output, "Recording to write (.jsonl)")->required();
  rec->add_flag("--overwrite", ro->overwrite, "Replace the output if it exists");
  rec->callback([ro, &exit_code] {
    const std::size_t n = record(ro->input, ro->params, {}, ro->output, ro->overwrite);
    std::cout << ro->output << ": " << n << " events\n";
    exit_code = 0;
  });

  auto so = std::make_shared<SynthOptions>();
  auto* syn = app.add_subcommand(
      "synth", "Write a synthetic session with ground truth (shorthand for record --input synthetic)");
  syn->add_option("model", so->model,
                  "cube, rounded_box, mug, chair, lamp, or an .off/.ply mesh (its feature curves)")
      ->required();
  syn->add_option("-o,--output", so->output, "Recording to write (default: MODEL.jsonl)");
  syn->add_option("--modality", so->modality, "vr (default) or tablet");
  syn->add_option("--noise", so->noise, "Global noise scale (default 1; 0 = perfect strokes)");
  syn->add_option("--seed", so->seed, "Random seed (default 1)");
  syn->add_option("--param", so->params, "Any other synthetic parameter key=value (repeatable)");
  syn->add_flag("--overwrite", so->overwrite, "Replace the output if it exists");
  syn->callback([so, &exit_code] {
    std::map<std::string, ParamValue> extra;
    const std::filesystem::path model(so->model);
    std::string ext = model.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    const bool mesh = ext == ".off" || ext == ".ply";
    if (mesh) {
      extra["model"] = std::string("mesh");
      extra["mesh"] = so->model;
    } else {
      extra["model"] = so->model;
    }
    if (so->modality) extra["modality"] = *so->modality;
    if (so->noise) extra["noise"] = *so->noise;
    if (so->seed) extra["seed"] = *so->seed;
    const std::string output =
        so->output.empty() ? (mesh ? model.stem().string() : so->model) + ".jsonl" : so->output;
    const std::size_t n = record("synthetic", so->params, extra, output, so->overwrite);
    std::cout << output << ": " << n << " events\n";
    exit_code = 0;
  });
}

}  // namespace sketchlab::cli
