#include <stdexcept>

#include "sketchlab/config/config.hpp"

namespace sketchlab {
namespace {

bool applies_to(const SweepAxis& axis, std::size_t stack) {
  return axis.path[1] == "*" || axis.path[1] == std::to_string(stack);
}

std::string dotted(const std::vector<std::string>& path) {
  std::string s;
  for (const auto& p : path) s += (s.empty() ? "" : ".") + p;
  return s;
}

}  // namespace

std::vector<SweepCase> expand_sweep(const ExperimentConfig& config) {
  std::vector<SweepCase> cases;
  for (std::size_t i = 0; i < config.stacks.size(); ++i) {
    std::vector<const SweepAxis*> axes;
    for (const auto& a : config.sweep)
      if (applies_to(a, i)) axes.push_back(&a);
    if (axes.empty()) {
      cases.push_back({config.stacks[i], {}});
      continue;
    }
    // Odometer over the axes, last axis fastest.
    std::vector<std::size_t> digit(axes.size(), 0);
    for (;;) {
      std::vector<Override> overrides = config.overrides;
      SweepCase c;
      std::string suffix;
      for (std::size_t k = 0; k < axes.size(); ++k) {
        std::vector<std::string> path = axes[k]->path;
        path[1] = std::to_string(i);
        const std::string& value = axes[k]->values[digit[k]];
        overrides.push_back({path, value});
        c.point.emplace_back(dotted(axes[k]->path), value);
        suffix += (suffix.empty() ? "@" : ",") + path.back() + "=" + value;
      }
      try {
        c.stack = load_experiment(config.file, overrides).stacks[i];
      } catch (const ConfigError& e) {
        std::string where;
        for (const auto* a : axes) where += (where.empty() ? "" : ", ") + a->location.to_string();
        throw ConfigError("sweep entry at " + where + ": " + e.what());
      }
      c.stack.name = config.stacks[i].name + suffix;
      cases.push_back(std::move(c));
      std::size_t k = axes.size();
      while (k > 0 && ++digit[k - 1] == axes[k - 1]->values.size()) digit[--k] = 0;
      if (k == 0) break;
    }
  }
  return cases;
}

}  // namespace sketchlab
