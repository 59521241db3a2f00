#pragma once
// Turning a stack config into live plugin objects, and replaying an input
// through them.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "sketchlab/config/config.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "sketchlab/session.hpp"

namespace sketchlab {

struct StackInstance {
  std::string name;
  std::shared_ptr<Corrector> corrector;
  std::shared_ptr<Surfacer> surfacer;  // may be null
  double time_budget_s = default_time_budget_s;  // per event (StackConfig::time_budget)
};

// Creates the corrector and surfacer of `stack`. Parameter errors become
// ConfigError naming the config file:line and the allowed values; an unknown
// plugin names the available ones.
StackInstance instantiate_stack(const StackConfig& stack, const PluginHost& host);

// `stack` with every parameter of its plugins written out, defaults
// included (the input too: default_input_plugin when it names none; its
// recording parameter is left out, each case sets it), validated as
// instantiate_stack does and with the same errors, without creating any
// plugin object: what a case runs, checked before anything is written.
StackConfig resolve_stack(const StackConfig& stack, const PluginHost& host);

// Creates the stack's input (default_input_plugin when it names none); an
// input that plays recording files (PluginDescriptor::recording_param, e.g.
// replay's `path`) gets `recording` there.
std::shared_ptr<Input> instantiate_input(const StackConfig& stack, const PluginHost& host,
                                         const std::filesystem::path& recording);

struct ReplayResult {
  std::string stack;
  RecordingHeader header;
  Session session;
  // One per event, plus a last "recompute_surface" step when the surfacer's
  // final Surfacer::recompute changed patches or failed.
  std::vector<StepReport> steps;
};

// Folds every event of `input` through a new session on `stack`. Throws
// std::runtime_error if the input reports an error (with its message).
ReplayResult replay(Input& input, const StackInstance& stack);

}  // namespace sketchlab
