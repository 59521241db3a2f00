#pragma once
// The stacks an interactive viewer (`sketchlab view`, `sketchlab vr`) runs:
// an experiment names its stacks, a stack file is one stack.
#include <filesystem>
#include <vector>

#include "sketchlab/config/config.hpp"

namespace sketchlab::viewer {

// The experiment's stacks when `file` is an experiment, else the one stack
// it holds. Throws ConfigError saying why it is neither (both reasons).
std::vector<StackConfig> load_viewer_stacks(const std::filesystem::path& file,
                                            const std::vector<Override>& overrides);

}  // namespace sketchlab::viewer
