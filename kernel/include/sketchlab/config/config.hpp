#pragma once
// Stacks and experiments read from YAML (DESIGN.md, "Configs").
//
// Stack file (or the value of one entry of an experiment's `stacks` list):
//
//   name: cassie-default          # optional for a stack file (file stem)
//   input:     {plugin: replay}                     # optional in experiments
//   corrector: {plugin: freehand, params: {delta: 0.02}}
//   surfacer:  {plugin: soapfilm}                   # optional
//   time_budget: 60               # optional: seconds per event (plugin/budget.hpp)
//
// Experiment file:
//
//   experiment: default
//   recordings: [../data/recordings/*.jsonl]   # files or globs, relative to the file
//   stacks: [ {name: freehand, corrector: {plugin: freehand}}, ... ]
//   outputs: {dir: runs, ply: false}           # every output is on by default
//
// Overrides `key.path=value` (e.g. `stacks.0.corrector.params.delta=0.03`,
// `outputs.dir=/tmp/x`) are applied to the YAML tree before validation; the
// value is parsed as YAML. Errors throw ConfigError naming file, line and
// the allowed values.
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sketchlab/plugin/params.hpp"

namespace sketchlab {

// Where a value came from, for error messages ("configs/a.yaml:12").
struct SourceLocation {
  std::string file;
  int line = 0;  // 1-based; 0 = command line override or default
  std::string to_string() const;
};

struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct PluginChoice {
  std::string plugin;  // plugin name
  std::map<std::string, ParamValue> params;
  std::map<std::string, SourceLocation> param_locations;
  SourceLocation location;  // of the `plugin:` key
};

// The input of a stack that names none: plays the experiment's recordings.
inline constexpr const char* default_input_plugin = "replay";

struct StackConfig {
  std::string name;
  std::optional<PluginChoice> input;  // default: default_input_plugin
  PluginChoice corrector;
  std::optional<PluginChoice> surfacer;
  // Seconds of corrector + surfacer time per event, in (0, 86400]; unset:
  // default_time_budget_s.
  std::optional<double> time_budget;
  SourceLocation location;
};

// Every output is on unless the config turns it off (`outputs: {ply: false}`).
struct OutputsConfig {
  std::filesystem::path dir = "runs";  // relative to the working directory
  bool sketch_json = true;
  bool stroke_csv = true;
  bool ply = true;
  bool obj = true;
  bool mlp = true;       // MeshLab project per recording (all stacks' layers)
  bool pictures = true;  // offscreen renders, side by side (needs the viewer)
  bool report = true;    // report.html, metrics.csv, metrics.json
  bool timestamp = true;  // run folder <dir>/<experiment>-<UTC timestamp>[-N]; false: <dir>/<experiment>[-N]
};

// One sweep axis: a parameter path inside a stack (`stacks.<index or *>....`)
// and the values it takes (as YAML text). An experiment's cases are every
// recording x every stack x the cartesian product of the axes that apply to
// that stack.
struct SweepAxis {
  std::vector<std::string> path;
  std::vector<std::string> values;
  SourceLocation location;
};

struct ExperimentConfig {
  std::string name;
  std::filesystem::path file;  // the YAML file it came from
  std::vector<std::filesystem::path> recordings;  // globs expanded, sorted, absolute
  std::vector<StackConfig> stacks;
  OutputsConfig outputs;
  std::vector<SweepAxis> sweep;
  std::vector<struct Override> overrides;  // as given to load_experiment
  // The experiment after overrides, recordings as absolute paths: loading it
  // again gives the same experiment (written into each run folder).
  std::string resolved_yaml;
};

// A stack as YAML (name, input, corrector, surfacer with their parameters),
// loadable with load_stack: the resolved configuration of one case.
std::string stack_to_yaml(const StackConfig& stack);

// One stack of an experiment at one sweep point.
struct SweepCase {
  StackConfig stack;  // name suffixed with the point, e.g. "cassie@delta=0.01"
  std::vector<std::pair<std::string, std::string>> point;  // dotted path -> value
};

// The stack variants of an experiment: each stack once when no sweep axis
// applies to it, else once per point of the cartesian product of its axes (in
// axis order, last axis fastest). Each variant is validated like a config
// (errors name the sweep entry's file:line). The file is read once; a sweep
// of more than max_sweep_points points in all is refused, naming its entries.
inline constexpr double max_sweep_points = 1e6;
std::vector<SweepCase> expand_sweep(const ExperimentConfig& config);

// "a.b.0.c=value" -> applied to the tree. Throws ConfigError on a malformed
// override (no '=' or empty key).
struct Override {
  std::vector<std::string> path;
  std::string value;  // YAML text
  // Where it was given: the command line (the default), or the sweep entry
  // that produced it. Errors about the value name this place.
  SourceLocation origin;
};
Override parse_override(const std::string& text);

// Throws ConfigError "<where>: <message>".
[[noreturn]] void throw_config_error(const SourceLocation& where, const std::string& message);

// Turns a ParamError from PluginHost::make_* into a ConfigError naming the
// file:line of that parameter in `choice` (of its `plugin:` key when the
// parameter was not set in the config) and the allowed values.
[[noreturn]] void rethrow_param_error(const ParamError& error, const PluginChoice& choice);

// Both throw ConfigError naming file:line (and the allowed keys or values) on
// unreadable YAML, unknown keys, values of the wrong type, missing required
// keys (`corrector`, `stacks`, `recordings`), duplicate stack names, a
// recording that does not exist or a glob that matches nothing. A plugin
// choice may be written as a map {plugin: NAME, params: {...}} or just NAME.
// Parameter values keep their YAML scalar type: true/false -> bool, integers
// -> int64, other numbers (and .inf/.nan) -> double, anything else (or
// quoted) -> string. Stack names default to the corrector plugin name, made
// unique with -2, -3, ... Recordings set by an override are relative to the
// working directory, the others to the config file.
ExperimentConfig load_experiment(const std::filesystem::path& file,
                                 const std::vector<Override>& overrides = {});
StackConfig load_stack(const std::filesystem::path& file,
                       const std::vector<Override>& overrides = {});

}  // namespace sketchlab
