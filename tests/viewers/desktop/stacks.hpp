#pragma once
// The stacks of configs/compare.yaml, built from the plugins of this build.
#include <vector>

#include "build_plugin_host.hpp"
#include "sketchlab/config/config.hpp"
#include "sketchlab/lab/stack.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "test_paths.hpp"

namespace sketchlab::test {

inline std::vector<StackInstance> compare_stacks() {
  std::vector<StackInstance> out;
  for (const StackConfig& c : load_experiment(source_path("configs/compare.yaml")).stacks)
    out.push_back(instantiate_stack(c, build_plugin_host()));
  return out;
}

}  // namespace sketchlab::test
