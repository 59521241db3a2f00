#include "sketchlab/lab/stack.hpp"

#include <stdexcept>

namespace sketchlab {

StackInstance instantiate_stack(const StackConfig& stack, const PluginHost& host) {
  StackInstance s;
  s.name = stack.name;
  if (stack.time_budget) s.time_budget_s = *stack.time_budget;
  try {
    s.corrector = host.make_corrector(stack.corrector.plugin, stack.corrector.params);
  } catch (const ParamError& e) {
    rethrow_param_error(e, stack.corrector);
  } catch (const PluginError& e) {
    throw ConfigError(stack.corrector.location.to_string() + ": " + e.what());
  }
  if (stack.surfacer) {
    try {
      s.surfacer = host.make_surfacer(stack.surfacer->plugin, stack.surfacer->params);
    } catch (const ParamError& e) {
      rethrow_param_error(e, *stack.surfacer);
    } catch (const PluginError& e) {
      throw ConfigError(stack.surfacer->location.to_string() + ": " + e.what());
    }
  }
  return s;
}

namespace {

void resolve_choice(PluginChoice& choice, PluginKind kind, const PluginHost& host,
                    const std::string& recording_param = {}) {
  try {
    auto given = choice.params;
    // A placeholder for the path each case sets: any string is valid.
    if (!recording_param.empty()) given[recording_param] = std::string();
    const Params resolved = host.resolve_params(kind, choice.plugin, given);
    choice.params = resolved.values();
    if (!recording_param.empty()) choice.params.erase(recording_param);
  } catch (const ParamError& e) {
    rethrow_param_error(e, choice);
  } catch (const PluginError& e) {
    throw ConfigError(choice.location.to_string() + ": " + e.what());
  }
}

}  // namespace

StackConfig resolve_stack(const StackConfig& stack, const PluginHost& host) {
  StackConfig s = stack;
  if (!s.input) {
    PluginChoice choice;
    choice.plugin = default_input_plugin;
    choice.location = stack.location;
    s.input = choice;
  }
  const LoadedPlugin* input = host.find(PluginKind::input, s.input->plugin);
  resolve_choice(*s.input, PluginKind::input, host, input ? input->descriptor->recording_param : std::string());
  resolve_choice(s.corrector, PluginKind::corrector, host);
  if (s.surfacer) resolve_choice(*s.surfacer, PluginKind::surfacer, host);
  if (!s.time_budget) s.time_budget = default_time_budget_s;
  return s;
}

std::shared_ptr<Input> instantiate_input(const StackConfig& stack, const PluginHost& host,
                                         const std::filesystem::path& recording) {
  PluginChoice choice;
  choice.plugin = default_input_plugin;
  choice.location = stack.location;
  if (stack.input) choice = *stack.input;
  try {
    // An input that plays files gets the recording (its descriptor names the
    // parameter); others (synthetic, live) ignore it.
    if (const LoadedPlugin* p = host.find(PluginKind::input, choice.plugin); p && !p->descriptor->recording_param.empty())
      choice.params[p->descriptor->recording_param] = recording.string();
    return host.make_input(choice.plugin, choice.params);
  } catch (const ParamError& e) {
    rethrow_param_error(e, choice);
  } catch (const PluginError& e) {
    throw ConfigError(choice.location.to_string() + ": " + e.what());
  }
}

ReplayResult replay(Input& input, const StackInstance& stack) {
  const RecordingHeader header = input.header();
  ReplayResult result{stack.name, header, Session(header.workspace, stack.corrector, stack.surfacer, {},
                                                       stack.time_budget_s),
                      {}};
  // A live input has nothing ready now and then (it paces itself): only its
  // end ends the replay.
  for (NextEvent event = input.next(); !event.is_ended(); event = input.next())
    if (event) result.steps.push_back(result.session.handle(*event));
  if (auto error = input.error(); !error.empty())
    throw std::runtime_error("input failed after " + std::to_string(result.steps.size()) +
                             " events: " + error);
  // Global surfacers (Surfacer::recompute) build their surface once, here; the
  // step is reported only when it did something, so surfacers that keep up
  // stroke by stroke leave the steps unchanged.
  if (stack.surfacer) {
    const double end = result.steps.empty() ? 0.0 : result.steps.back().time;
    StepReport last = result.session.handle(Event{end, RecomputeSurfaceEvent{}});
    if (last.patches_added + last.patches_removed > 0 || !last.error.empty())
      result.steps.push_back(std::move(last));
  }
  return result;
}

}  // namespace sketchlab
