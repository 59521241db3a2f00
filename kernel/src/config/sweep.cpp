#include <sstream>
#include <stdexcept>

#include "config_internal.hpp"

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
  std::vector<std::vector<const SweepAxis*>> axes_of(config.stacks.size());
  double points = 0.0;
  for (std::size_t i = 0; i < config.stacks.size(); ++i) {
    double product = 1.0;
    for (const auto& a : config.sweep)
      if (applies_to(a, i)) {
        axes_of[i].push_back(&a);
        product *= static_cast<double>(a.values.size());
      }
    points += product;
  }
  if (points > max_sweep_points) {
    std::string where;
    for (const auto& a : config.sweep) where += (where.empty() ? "" : ", ") + a.location.to_string();
    std::ostringstream text;
    text << "sweep entries at " << where << ": the sweep has " << points
         << " stack variants in all; at most " << max_sweep_points << " are allowed";
    throw ConfigError(text.str());
  }

  // The file is read once; each point only applies its values to a copy.
  YAML::Node root;
  if (!config.sweep.empty()) root = config_detail::load_yaml(config.file);
  std::vector<SweepCase> cases;
  for (std::size_t i = 0; i < config.stacks.size(); ++i) {
    const auto& axes = axes_of[i];
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
        overrides.push_back({path, value, axes[k]->location});
        c.point.emplace_back(dotted(axes[k]->path), value);
        suffix += (suffix.empty() ? "@" : ",") + path.back() + "=" + value;
      }
      c.stack = config_detail::read_experiment_stack(root, config.file, overrides, i);
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
