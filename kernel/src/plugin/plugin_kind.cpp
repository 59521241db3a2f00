#include <stdexcept>
#include <string>

#include "sketchlab/plugin/plugin_api.hpp"

namespace sketchlab {

std::string_view to_string(PluginKind kind) {
  switch (kind) {
    case PluginKind::corrector: return "corrector";
    case PluginKind::surfacer: return "surfacer";
    case PluginKind::input: return "input";
  }
  return "unknown";
}

PluginKind plugin_kind_from_string(std::string_view name) {
  for (auto kind : {PluginKind::corrector, PluginKind::surfacer, PluginKind::input}) {
    if (to_string(kind) == name) return kind;
  }
  throw std::invalid_argument("unknown plugin kind '" + std::string(name) +
                              "'; allowed: corrector, surfacer, input");
}

}  // namespace sketchlab
