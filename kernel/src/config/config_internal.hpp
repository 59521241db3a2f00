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
// Throws ConfigError naming the override and where it was given.
void apply_overrides(YAML::Node& root, const std::vector<Override>& overrides);

// "a.b.0.c" -> {"a", "b", "0", "c"} (segments trimmed). Throws
// std::invalid_argument for an empty key or an empty segment.
std::vector<std::string> split_key_path(const std::string& key);

// The YAML tree of a config file (an empty map for an empty file). Throws
// ConfigError "file: cannot read" or "file:line: invalid YAML: ...".
YAML::Node load_yaml(const std::filesystem::path& file);

// Stack `index` of the experiment tree `root` (read from `file`) after
// `overrides`, validated as load_experiment validates it; its name is left
// as written (possibly empty). `root` is not modified.
StackConfig read_experiment_stack(const YAML::Node& root, const std::filesystem::path& file,
                                  const std::vector<Override>& overrides, std::size_t index);

// Regular files named by `pattern` (glob(3): *, ? and [...] in any
// component; leading dots matched only explicitly),
// relative to `base` unless absolute: absolute, lexically normal, sorted.
// Throws std::runtime_error when nothing matches or the pattern is invalid.
std::vector<std::filesystem::path> expand_pattern(const std::string& pattern,
                                                  const std::filesystem::path& base);

}  // namespace sketchlab::config_detail
