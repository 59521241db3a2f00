#include <yaml-cpp/yaml.h>

#include "sketchlab/config/config.hpp"

namespace sketchlab {
namespace {

void emit_choice(YAML::Emitter& out, const char* key, const PluginChoice& choice) {
  out << YAML::Key << key << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "plugin" << YAML::Value << choice.plugin;
  if (!choice.params.empty()) {
    out << YAML::Key << "params" << YAML::Value << YAML::BeginMap;
    for (const auto& [name, value] : choice.params) {
      out << YAML::Key << name << YAML::Value;
      // Strings are quoted so that "true" or "1" stay strings when read back.
      if (auto* s = std::get_if<std::string>(&value))
        out << YAML::DoubleQuoted << *s;
      else
        out << format_value(value);
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

}  // namespace

std::string stack_to_yaml(const StackConfig& stack) {
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << "name" << YAML::Value << stack.name;
  if (stack.input) emit_choice(out, "input", *stack.input);
  emit_choice(out, "corrector", stack.corrector);
  if (stack.surfacer) emit_choice(out, "surfacer", *stack.surfacer);
  if (stack.time_budget) out << YAML::Key << "time_budget" << YAML::Value << *stack.time_budget;
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace sketchlab
