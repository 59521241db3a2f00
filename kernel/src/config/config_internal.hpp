#pragma once
// Pieces of the config loader shared between its source files (not public).
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>
#include <vector>

#include "sketchlab/config/config.hpp"

namespace sketchlab::config_detail {

// Applies each override to `root` in order. A path into a missing map key
// creates it (and maps on the way); a list step must be an existing index.
// Throws ConfigError naming the override.
void apply_overrides(YAML::Node& root, const std::vector<Override>& overrides);

// True when `name` matches `pattern` ('*' any run, '?' one character; a
// leading '.' in name must be matched literally, as in a shell).
bool glob_match(std::string_view pattern, std::string_view name);

// Files named by `pattern` (wildcards allowed in its last component only),
// relative to `base` unless absolute: absolute, lexically normal, sorted.
// Throws std::runtime_error when nothing matches or the pattern is invalid.
std::vector<std::filesystem::path> expand_pattern(const std::string& pattern,
                                                  const std::filesystem::path& base);

}  // namespace sketchlab::config_detail
