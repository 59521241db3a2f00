#include "sketchlab/config/config.hpp"

namespace sketchlab {

std::string SourceLocation::to_string() const {
  if (line > 0) return file + ":" + std::to_string(line);
  return file.empty() ? "command line" : file;
}

void throw_config_error(const SourceLocation& where, const std::string& message) {
  throw ConfigError(where.to_string() + ": " + message);
}

void rethrow_param_error(const ParamError& error, const PluginChoice& choice) {
  auto it = choice.param_locations.find(error.parameter);
  const SourceLocation& where = it != choice.param_locations.end() ? it->second : choice.location;
  throw_config_error(where, "plugin '" + choice.plugin + "': " + error.what());
}

}  // namespace sketchlab
