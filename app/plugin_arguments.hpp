#pragma once
// Plugins for the command line: loading them with warnings, and
// `--param key=value` arguments typed by a plugin's parameter specs.
#include <map>
#include <string>
#include <vector>

#include "sketchlab/plugin/plugin_host.hpp"

namespace sketchlab::cli {

// Loads the plugins from the default search paths; each library that failed
// is reported on stderr as a warning (path and reason).
void load_plugins(PluginHost& host);

// "k=v" texts -> values of the types the plugin's specs declare (ParamError
// naming the parameter and allowed values when one does not parse). Names the
// plugin does not declare are passed as strings so validation reports them
// with the declared list. Throws std::invalid_argument for text without '='.
std::map<std::string, ParamValue> parse_param_arguments(const LoadedPlugin& plugin,
                                                        const std::vector<std::string>& texts);

}  // namespace sketchlab::cli
