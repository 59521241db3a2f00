#include "plugin_arguments.hpp"

#include <algorithm>
#include <iostream>
#include <stdexcept>

namespace sketchlab::cli {

void load_plugins(PluginHost& host) {
  host.load_directories(PluginHost::default_search_paths());
  for (const auto& e : host.errors())
    std::cerr << "warning: plugin " << e.path.string() << " not loaded: " << e.reason << "\n";
}

std::map<std::string, ParamValue> parse_param_arguments(const LoadedPlugin& plugin,
                                                        const std::vector<std::string>& texts) {
  std::map<std::string, ParamValue> out;
  for (const std::string& text : texts) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
      throw std::invalid_argument("--param expects key=value, got '" + text + "'");
    const std::string key = text.substr(0, eq), value = text.substr(eq + 1);
    const auto& specs = plugin.descriptor->params;
    const auto spec = std::find_if(specs.begin(), specs.end(), [&](const ParamSpec& s) { return s.name == key; });
    out[key] = spec == specs.end() ? ParamValue(value) : parse_param_value(*spec, value);
  }
  return out;
}

}  // namespace sketchlab::cli
