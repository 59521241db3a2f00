#include "sketchlab/viewer/viewer_stacks.hpp"

namespace sketchlab::viewer {

std::vector<StackConfig> load_viewer_stacks(const std::filesystem::path& file,
                                            const std::vector<Override>& overrides) {
  try {
    return load_experiment(file, overrides).stacks;
  } catch (const ConfigError& experiment_error) {
    try {
      return {load_stack(file, overrides)};
    } catch (const ConfigError& stack_error) {
      throw ConfigError(std::string("not an experiment (") + experiment_error.what() + ") nor a stack (" +
                        stack_error.what() + ")");
    }
  }
}

}  // namespace sketchlab::viewer
